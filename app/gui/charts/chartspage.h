// ChartsPage: tip curves over time. Per port: tip temperature and setpoint (°C or °F) and power
// (% on the right axis), every port overlaid or one pane per port, and the feeder's fed length
// and speed in a pane of its own; alarm limits as shaded bands, event markers (status changes,
// errors, alarms, writes) with tooltips; a time window of 30 s to 24 h that follows the newest
// data or stays paused; wheel zoom, drag pan, rubber-band zoom and reset; a crosshair readout of
// every series under the cursor; heat-up, recovery and min/max/mean of the visible window; PNG
// and CSV export of the window, continuous CSV recording, and replay of a recorded CSV, read on a
// thread of its own behind a progress dialog with Cancel, so the page stays live meanwhile.
//
// Bounded work: redraws are coalesced on a timer, at most kMaxRedrawsPerSecond and, while
// following, no more often than the window moves by a pixel column; each asks the telemetry for
// the window decimated to the plot's width (ChartFrame), so its cost depends on pixels, not on
// history. Nothing is drawn while the page is hidden. Measurements, which read more, are
// refreshed at most once a second.
//
// The page never holds history itself: live it reads the session's telemetry, in replay a
// ChartRecording it owns. Only ChartWidget touches Qt Charts.
#pragma once

#include "model/chart/chartevents.h"
#include "model/chart/chartseries.h"
#include "model/chart/chartviewport.h"

#include "pages/page.h"

#include <QElapsedTimer>
#include <QTimer>
#include <memory>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QToolButton;
class QVBoxLayout;

class QProgressDialog;

namespace tipscope::model {
class ChartRecorder;
struct ChartRecording;
class RecordingLoader;
} // namespace tipscope::model

namespace tipscope::gui {

class ChartWidget;
class ElidedLabel;
class ReadoutPanel;
struct ChartBand;
struct ChartMarker;
struct ChartSeriesStyle;

class ChartsPage : public Page {
    Q_OBJECT
public:
    static constexpr int kMaxRedrawsPerSecond = 20;
    // How the panes share the height: a station's pane twice the feeder's, whose two curves
    // need less room than four ports' temperatures and power.
    static constexpr int kStationStretch = 2;
    static constexpr int kFeederStretch = 1;
    // Below this page height the measurements start folded, so the plots keep their room.
    static constexpr int kMeasurementsFromHeight = 700;
    enum class Layout { Overlaid, PerPort };

    explicit ChartsPage(model::Session &session, QWidget *parent = nullptr);
    ~ChartsPage() override;

    [[nodiscard]] QString title() const override { return tr("Charts"); }
    [[nodiscard]] QSet<int> visiblePorts() const override;
    void setActive(bool active) override;

    void setPaneLayout(Layout layout);
    [[nodiscard]] model::ChartViewport &viewport() { return m_viewport; }
    // Station panes first, then the feeder's.
    [[nodiscard]] QList<ChartWidget *> panes() const;
    [[nodiscard]] QList<model::ChartTrace> traces(int pane) const;
    // Redraws now instead of at the next coalesced tick (tests, the bench, exports).
    void redrawNow();
    [[nodiscard]] qint64 redrawCount() const { return m_redraws; }
    [[nodiscard]] QString readoutText() const;
    [[nodiscard]] QString measurementText() const;
    void setTolerance(double display);
    void updateMeasurements();
    [[nodiscard]] bool measurementsShown() const;

    // The charts drawn afresh at `size` (the default: the larger of 1920×1080 and twice the
    // panes on screen), with the devices, the date and the time range above them, full axis
    // titles and legends. Each export returns an error, or empty on success; a file is replaced
    // whole or not at all.
    QString exportPng(const QString &path, QSize size = {});
    [[nodiscard]] QSize defaultPngSize() const;
    QString exportCsv(const QString &path);
    QString startRecording(const QString &path);
    void stopRecording();
    [[nodiscard]] bool isRecording() const;
    // Starts reading a recording; replayOpened() follows. The live view stays until it is read.
    void openReplay(const QString &path);
    [[nodiscard]] bool isLoadingReplay() const;
    void cancelReplayLoad();
    void showLive();
    // The live charts around [fromMs, toMs] (a joint), with some time either side, paused there.
    // The charts show every device; `device` is whose readings must cover the moment. Empty
    // when shown, else why not (the session holds no readings of that device then).
    QString showMoment(const model::DeviceIdentity &device, qint64 fromMs, qint64 toMs);
    [[nodiscard]] bool isReplay() const { return m_replay != nullptr; }
    // What the charts show: the session's telemetry live, the recording's in replay.
    [[nodiscard]] const model::Telemetry &shownTelemetry() const;
    [[nodiscard]] const QList<model::ChartChannel> &shownChannels() const;

protected:
    void resizeEvent(QResizeEvent *event) override;

Q_SIGNALS:
    // After openReplay(): empty when the recording is shown, else why not (cancelled included).
    void replayOpened(const QString &error);

private:
    struct Pane {
        ChartWidget *widget = nullptr;
        QList<int> channels;
        QList<model::ChartTrace> traces;
    };

    void buildToolbar(QVBoxLayout *layout);
    void buildReadout(QVBoxLayout *layout);
    void updateReadoutTemplate();
    void buildMeasurements(QVBoxLayout *layout);
    void showMeasurements(bool shown);
    void showWindowLength();
    [[nodiscard]] static QString softwareVersion();
    [[nodiscard]] static QString suggestedPath(const QString &suffix);
    [[nodiscard]] QString sourceText() const;
    [[nodiscard]] QString rangeText() const;
    [[nodiscard]] std::optional<QSize> choosePngSize();
    // A pane's chart, titled and labelled; `roomy` gives the value axes their full titles.
    [[nodiscard]] ChartWidget *createPaneWidget(const Pane &pane, bool roomy,
                                                QWidget *parent) const;
    void rebuildPanes();
    void connectPane(ChartWidget *widget);
    void resetView();
    void scheduleRedraw();
    void redraw();
    void drawPane(Pane &pane);
    void onSamplesAdded();
    void onHover(qint64 timeMs);
    void onLeave();
    void refreshLiveChannels();
    void updateSourceLabel();
    void chooseAndExport(bool png);
    void toggleRecording(bool on);
    void chooseReplay();
    void showReplayProgress();
    void onReplayLoaded(const QString &error);
    [[nodiscard]] const model::ChartEvents &events() const;
    [[nodiscard]] QList<ChartMarker> markersFor(const Pane &pane) const;
    [[nodiscard]] QList<ChartBand> bandsFor(const Pane &pane) const;
    [[nodiscard]] static QList<ChartSeriesStyle>
    overlaidLegend(const QList<model::ChartChannel> &cs, const Pane &pane);

    model::ChartViewport m_viewport;
    QTimer m_redrawTimer;
    QTimer m_measureTimer;
    QElapsedTimer m_sinceRedraw;
    qint64 m_redraws = 0;
    Layout m_layout = Layout::Overlaid;
    QList<model::ChartChannel> m_liveChannels;
    model::ChartEvents m_liveEvents;
    std::unique_ptr<model::ChartRecording> m_replay;
    QString m_replayPath;
    model::RecordingLoader *m_loader;
    QProgressDialog *m_loadProgress = nullptr;
    model::ChartRecorder *m_recorder;
    QList<Pane> m_panes;
    std::optional<qint64> m_hover;

    QVBoxLayout *m_panesLayout = nullptr;
    QWidget *m_panesHost = nullptr;
    QComboBox *m_window = nullptr;
    QComboBox *m_layoutBox = nullptr;
    QToolButton *m_follow = nullptr;
    QToolButton *m_hardware = nullptr; // checked: transistor and transformer curves too
    QToolButton *m_record = nullptr;
    QToolButton *m_live = nullptr;
    ElidedLabel *m_source = nullptr;
    ReadoutPanel *m_readout = nullptr;
    QToolButton *m_measureToggle = nullptr;
    bool m_measureChosen = false; // folded or unfolded by hand: the page no longer decides
    QDoubleSpinBox *m_tolerance = nullptr;
    QPlainTextEdit *m_measurements = nullptr;
};

} // namespace tipscope::gui
