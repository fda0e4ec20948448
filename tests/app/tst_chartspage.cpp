// The Charts page through its real widgets against the demo line (a simulated DME-4C at 01 and
// an SFR at 10 on a 19200 Bd wire, so the tests wait for real polls): panes and curves, event
// markers for status changes injected in the simulator, the crosshair readout after zoom and pan,
// export, recording and replay (read off the GUI thread, with progress and cancel).
#include "charts/chartspage.h"
#include "charts/chartwidget.h"
#include "model/chart/chartframe.h"
#include "model/device/feedermodel.h"
#include "model/recording/chartcsvreader.h"
#include "support/fifowriter.h"
#include "testmain.h"

#include "demosession.h"
#include "sim/simline.h"
#include "sim/simstation.h"

#include <QApplication>
#include <QComboBox>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QMouseEvent>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QStyleOptionComboBox>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QWheelEvent>
#include <memory>

namespace tst_chartspage {

using namespace tipscope;
using namespace tipscope::gui;
using namespace tipscope::model;

namespace {
constexpr int kConnectMs = 30000;
constexpr int kDataMs = 20000;

void sendMouse(QWidget *w, QEvent::Type type, QPointF pos, Qt::MouseButton button,
               Qt::MouseButtons buttons) {
    QMouseEvent event(type, pos, w->mapToGlobal(pos), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(w, &event);
}
} // namespace

class TestChartsPage : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void everyPortOfTheDemoStationIsDrawnLive();
    void statusChangesInjectedInTheSimulatorGetMarkers();
    void zoomAndPanKeepTheCrosshairReadoutConsistentWithTheBuffer();
    void exportedCsvReplaysTheSameSamples();
    void aMalformedRecordingIsRefusedAndTheLiveViewStays();
    void aReplayIsReadWithProgressAndCancelWhileTheLiveChartsGoOn();
    void aLongRecordingNameNeverWidensThePage();
    void recordingWritesTheNewSamplesToTheFile();
    void pngExportRendersTheChartsAtTheChosenSize();
    void onePanePerPortOnRequest();
    void theWindowBoxShowsAZoomedLengthWhole();
    void hardwareTemperaturesAreDrawnOnRequest();
    void theFeedersSeriesStartAtTheirFirstReadings();
    void theDemoAtWorkShowsAJointsRecoveryAndTheFeederFeeding();

private:
    void connectDemo();
    void waitForSamples(int count);
    // openReplay() and its outcome: empty when the recording is shown.
    QString replay(const QString &path);
    [[nodiscard]] ChartWidget *stationPane() const { return m_page->panes().value(0); }
    [[nodiscard]] QString logText() const {
        QStringList lines;
        for (const model::Event &e : m_session->eventLog().events())
            lines.append(e.source + QStringLiteral(": ") + e.text);
        return lines.join(QLatin1Char('\n'));
    }

    std::unique_ptr<Session> m_session;
    std::unique_ptr<ChartsPage> m_page;
    QTemporaryDir m_dir;
};

void TestChartsPage::init() {
    m_session = std::make_unique<Session>();
    m_page = std::make_unique<ChartsPage>(*m_session);
    m_page->resize(1200, 800);
    m_page->show();
    m_page->setActive(true);
    connectDemo();
}

void TestChartsPage::cleanup() {
    m_page.reset();
    m_session.reset();
}

void TestChartsPage::connectDemo() {
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected, kConnectMs);
    m_session->scheduler().setVisiblePorts(m_session->station(), m_page->visiblePorts());
}

void TestChartsPage::waitForSamples(int count) {
    const QString key = TelemetryRecorder::keyOf(*m_session->station(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->telemetry().buffer(key)->size() >= count, kDataMs);
}

QString TestChartsPage::replay(const QString &path) {
    QSignalSpy opened(m_page.get(), &ChartsPage::replayOpened);
    if (!opened.isValid())
        return QStringLiteral("no replayOpened signal");
    m_page->openReplay(path);
    if (!opened.wait(kDataMs))
        return QStringLiteral("the replay did not finish");
    return opened.first().first().toString();
}

void TestChartsPage::everyPortOfTheDemoStationIsDrawnLive() {
    QCOMPARE(m_page->visiblePorts().size(), 4);
    QCOMPARE(m_page->panes().size(), 2); // the ports overlaid, and the feeder
    QCOMPARE(stationPane()->seriesCount(), 12);
    QCOMPARE(m_page->traces(1).size(), 2); // fed length and speed
    waitForSamples(5);
    QTRY_VERIFY_WITH_TIMEOUT(stationPane()->pointCount(0) > 0, kDataMs); // by the page's timer
    for (int i = 0; i < 12; ++i)
        QVERIFY2(stationPane()->pointCount(i) > 0, qPrintable(m_page->traces(0).at(i).name));
    QVERIFY(m_page->viewport().isFollowing());
    m_page->redrawNow();
    QCOMPARE(stationPane()->timeEnd(), m_page->viewport().end());
    QVERIFY(m_page->redrawCount() > 0);
}

void TestChartsPage::statusChangesInjectedInTheSimulatorGetMarkers() {
    waitForSamples(3);
    // A change is logged against a value already read: wait for the first readings.
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station()->port(2)->status().has_value() &&
                                 m_session->station()->port(3)->error().has_value(),
                             kDataMs);
    m_session->demoLine()->station()->setStatus(2, 1); // port 2 into the stand
    m_session->demoLine()->station()->setPortError(3, 4);
    const auto tooltips = [this] {
        m_page->redrawNow();
        QStringList all;
        for (ChartWidget *pane : m_page->panes())
            for (double x = pane->plotArea().left(); x <= pane->plotArea().right(); x += 4)
                if (const QString tip = pane->markerTooltipAt(x); !all.contains(tip))
                    all.append(tip);
        return all.join(QLatin1Char('\n'));
    };
    // The demo's tool sleeps at once in the stand, so the first reading may already say Sleep.
    QTRY_VERIFY2_WITH_TIMEOUT(tooltips().contains(QStringLiteral("Port 2 · Status: Working → ")),
                              qPrintable(tooltips() + QStringLiteral(" | log: ") + logText()),
                              kDataMs);
    QTRY_VERIFY2_WITH_TIMEOUT(tooltips().contains(QStringLiteral("Port 3 · Port error: ")),
                              qPrintable(tooltips() + QStringLiteral(" | log: ") + logText()),
                              kDataMs);
    // Port 2's marker is not on the feeder's pane.
    ChartWidget *feeder = m_page->panes().value(1);
    for (double x = feeder->plotArea().left(); x <= feeder->plotArea().right(); x += 4)
        QVERIFY(!feeder->markerTooltipAt(x).contains(QStringLiteral("Port 2")));
}

void TestChartsPage::zoomAndPanKeepTheCrosshairReadoutConsistentWithTheBuffer() {
    waitForSamples(40);
    // A heating tip is read as fast as the wire allows: wait for history to hover over, too.
    const auto *tips =
        m_session->telemetry().buffer(TelemetryRecorder::keyOf(*m_session->station(), 1));
    QTRY_VERIFY_WITH_TIMEOUT(tips->lastTime() - tips->firstTime() >= 4000, kDataMs);
    m_page->redrawNow();
    ChartWidget *pane = stationPane();
    QWidget *surface = pane->plotSurface();
    const QRectF plot = pane->plotArea();
    // From five minutes (while less data than that fills the view, the window is shorter):
    // zoom in twice about a point right of the middle, then drag the view to the right.
    m_page->viewport().setFollowing(false);
    m_page->viewport().setWindowLength(ChartViewport::kDefaultWindowMs);
    m_page->redrawNow();
    const QPointF at(plot.left() + plot.width() * 0.8, plot.center().y());
    for (int notch = 0; notch < 2; ++notch) {
        QWheelEvent wheel(at, surface->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(surface, &wheel);
    }
    QVERIFY(!m_page->viewport().isFollowing());
    QCOMPARE(m_page->viewport().windowMs(), qint64(ChartViewport::kDefaultWindowMs * 0.64));
    sendMouse(surface, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    sendMouse(surface, QEvent::MouseMove, at + QPointF(60, 0), Qt::NoButton, Qt::LeftButton);
    sendMouse(surface, QEvent::MouseButtonRelease, at + QPointF(60, 0), Qt::LeftButton,
              Qt::NoButton);
    m_page->redrawNow();
    QCOMPARE(pane->timeStart(), m_page->viewport().start());
    QCOMPARE(pane->timeEnd(), m_page->viewport().end());

    // Hover over data: the readout is the buffer's newest sample at or before that instant.
    const double x = pane->xAt(tips->lastTime() - 2000);
    QVERIFY(plot.contains(QPointF(x, plot.center().y())));
    sendMouse(surface, QEvent::MouseMove, QPointF(x, plot.center().y()), Qt::NoButton,
              Qt::NoButton);
    const qint64 t = pane->timeAt(x);
    const QList<ChartTrace> traces = m_page->traces(0);
    const QList<ReadoutValue> values =
        readoutAt(m_session->telemetry(), sessionChannels(*m_session), traces, t);
    QVERIFY(tips->valueAt(0, t));
    QCOMPARE(values.at(0).wire, tips->valueAt(0, t)->value);
    QCOMPARE(values.at(0).sampleMs, tips->valueAt(0, t)->timeMs);
    QVERIFY2(m_page->readoutText().contains(readoutText(traces, values, t)),
             qPrintable(m_page->readoutText()));
    // The crosshair's pixel is where Qt Charts itself draws that instant.
    QVERIFY(qAbs(pane->seriesPosition(0, QPointF(double(t), 300)).x() - x) < 1.0);
}

void TestChartsPage::exportedCsvReplaysTheSameSamples() {
    waitForSamples(20);
    m_page->redrawNow(); // the view follows the samples that came, however fast they came
    m_page->viewport().setFollowing(false); // a fixed window to export and compare
    const qint64 t0 = m_page->viewport().start(), t1 = m_page->viewport().end();
    const QString path = m_dir.filePath(QStringLiteral("window.csv"));
    QCOMPARE(m_page->exportCsv(path), QString());
    // What was exported: the live session goes on while the replay is read.
    const QList<ChartChannel> live = sessionChannels(*m_session);
    QList<QList<QList<model::TelemetryBuffer::Sample>>> exported;
    for (const ChartChannel &c : live) {
        const auto *from = m_session->telemetry().buffer(c.key);
        exported.append(QList<QList<model::TelemetryBuffer::Sample>>());
        for (int s = 0; s < from->seriesCount(); ++s)
            exported.last().append(from->samples(s, t0, t1));
    }
    QCOMPARE(replay(path), QString());
    QVERIFY(m_page->isReplay());
    QCOMPARE(m_page->panes().size(), 2);
    m_page->redrawNow();
    QVERIFY(stationPane()->pointCount(0) > 0);
    // Every live sample of the window is in the replay (keyed by channel id), unchanged.
    QCOMPARE(m_page->shownChannels().size(), live.size());
    for (qsizetype c = 0; c < live.size(); ++c) {
        const auto *from = m_session->telemetry().buffer(live.at(c).key);
        const auto *back = m_page->shownTelemetry().buffer(live.at(c).id);
        QVERIFY2(back, qPrintable(live.at(c).id));
        QCOMPARE(back->seriesNames(), from->seriesNames());
        for (int s = 0; s < from->seriesCount(); ++s) {
            const auto &expected = exported.at(c).at(s);
            const auto replayed = back->samples(s, t0, t1);
            QCOMPARE(replayed.size(), expected.size());
            for (qsizetype i = 0; i < expected.size(); ++i) {
                QCOMPARE(replayed.at(i).timeMs, expected.at(i).timeMs);
                QCOMPARE(replayed.at(i).value, expected.at(i).value);
            }
        }
    }
    m_page->showLive();
    QVERIFY(!m_page->isReplay());
    QVERIFY(m_page->viewport().isFollowing());
}

void TestChartsPage::aMalformedRecordingIsRefusedAndTheLiveViewStays() {
    const QString path = m_dir.filePath(QStringLiteral("bad.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("time,port1 tip [°C],events\n2024-01-01T00:00:00.000Z,hot,\n");
    file.close();
    const QString error = replay(path);
    QVERIFY2(error.contains(QStringLiteral("bad.csv, line 2")), qPrintable(error));
    QVERIFY2(error.contains(QStringLiteral("\"hot\" is not a number")), qPrintable(error));
    QVERIFY(!m_page->isReplay());
    QCOMPARE(m_page->panes().size(), 2);
}

void TestChartsPage::aReplayIsReadWithProgressAndCancelWhileTheLiveChartsGoOn() {
#ifdef Q_OS_UNIX
    waitForSamples(3);
    // A FIFO that sends a little and then nothing: read in the GUI thread, it would freeze it.
    FifoWriter writer(m_dir, "# TipScope chart data, format 1\n", false);
    QVERIFY(writer.ok());
    QSignalSpy opened(m_page.get(), &ChartsPage::replayOpened);
    QVERIFY(opened.isValid());
    m_page->openReplay(writer.path());
    QVERIFY(m_page->isLoadingReplay());
    QProgressDialog *progress = nullptr;
    QTRY_VERIFY_WITH_TIMEOUT(
        (progress = m_page->findChild<QProgressDialog *>(QStringLiteral("replayProgress"))) &&
            progress->isVisible(),
        kDataMs);
    QVERIFY2(progress->labelText().contains(QStringLiteral("fifo.csv")),
             qPrintable(progress->labelText()));
    // Meanwhile the live charts go on: new samples are drawn.
    const qint64 redraws = m_page->redrawCount();
    const QString key = TelemetryRecorder::keyOf(*m_session->station(), 1);
    const qint64 samples = m_session->telemetry().buffer(key)->totalAppended();
    QTRY_VERIFY_WITH_TIMEOUT(m_page->redrawCount() > redraws + 2 &&
                                 m_session->telemetry().buffer(key)->totalAppended() > samples,
                             kDataMs);
    QVERIFY(opened.isEmpty());
    auto *cancel = progress->findChild<QPushButton *>();
    QVERIFY(cancel);
    cancel->click();
    QVERIFY(opened.wait(kDataMs));
    QVERIFY2(opened.first().first().toString().endsWith(ChartCsvReader::cancelledText()),
             qPrintable(opened.first().first().toString()));
    QVERIFY(!m_page->isLoadingReplay());
    QVERIFY(!m_page->isReplay());
    QCOMPARE(m_page->panes().size(), 2);
#else
    QSKIP("FIFOs are a Unix thing");
#endif
}

void TestChartsPage::recordingWritesTheNewSamplesToTheFile() {
    waitForSamples(3);
    const QString path = m_dir.filePath(QStringLiteral("rec.csv"));
    QCOMPARE(m_page->startRecording(path), QString());
    QVERIFY(m_page->isRecording());
    const QString key = TelemetryRecorder::keyOf(*m_session->station(), 1);
    const qint64 before = m_session->telemetry().buffer(key)->totalAppended();
    QTRY_VERIFY_WITH_TIMEOUT(m_session->telemetry().buffer(key)->totalAppended() >= before + 8,
                             kDataMs);
    m_page->stopRecording();
    QVERIFY(!m_page->isRecording());
    QCOMPARE(replay(path), QString());
    QVERIFY(m_page->isReplay());
    const auto *recorded = m_page->shownTelemetry().buffer(QStringLiteral("port1"));
    QVERIFY(recorded);
    QVERIFY2(recorded->size() >= 8, qPrintable(QString::number(recorded->size())));
    QVERIFY(recorded->firstTime() > m_session->telemetry().buffer(key)->firstTime());
    m_page->redrawNow();
    QVERIFY(stationPane()->pointCount(0) > 0);
}

// Drawn afresh at the size asked for, not a grab of the window: by default at least 1920×1080
// or twice the panes on screen.
void TestChartsPage::pngExportRendersTheChartsAtTheChosenSize() {
    waitForSamples(3);
    const QString path = m_dir.filePath(QStringLiteral("chart.png"));
    QCOMPARE(m_page->exportPng(path, QSize(2560, 1440)), QString());
    const QImage image(path);
    QCOMPARE(image.size(), QSize(2560, 1440));
    const QSize byDefault = m_page->defaultPngSize();
    QVERIFY(byDefault.width() >= 1920 && byDefault.height() >= 1080);
    QVERIFY(byDefault.width() >= 2 * m_page->panes().first()->width());
    QCOMPARE(m_page->exportPng(path), QString());
    QCOMPARE(QImage(path).size(), byDefault);
    // The window on screen is as it was: the export drew charts of its own.
    QCOMPARE(m_page->panes().size(), 2);
    QVERIFY(m_page->panes().first()->width() < byDefault.width());
    // A failed export says why and leaves the last good file.
    const QString error = m_page->exportPng(QStringLiteral("/no/such/folder/chart.png"));
    QVERIFY2(error.startsWith(QStringLiteral("cannot write")), qPrintable(error));
    QCOMPARE(QImage(path).size(), byDefault);
}

// A zoom shows its own length in the window box ("3 min 12 s"), whole, not "3 min 1".
void TestChartsPage::theWindowBoxShowsAZoomedLengthWhole() {
    waitForSamples(10);
    auto *box = m_page->findChild<QComboBox *>(QStringLiteral("windowCombo"));
    QVERIFY(box);
    m_page->viewport().setFollowing(false);
    m_page->viewport().setWindowLength(qint64(ChartViewport::kDefaultWindowMs * 0.64));
    m_page->redrawNow();
    QCOMPARE(box->currentData().toLongLong(), qint64(ChartViewport::kDefaultWindowMs * 0.64));
    QStyleOptionComboBox option;
    option.initFrom(box);
    auto room = [box, &option] {
        option.rect = box->rect();
        return box->style()
            ->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, box)
            .width();
    };
    const int text = box->fontMetrics().horizontalAdvance(box->currentText());
    QTRY_VERIFY2(room() >= text, qPrintable(QStringLiteral("\"%1\" needs %2 px, has %3")
                                                .arg(box->currentText())
                                                .arg(text)
                                                .arg(room())));
}

void TestChartsPage::onePanePerPortOnRequest() {
    m_page->setPaneLayout(ChartsPage::Layout::PerPort);
    QCOMPARE(m_page->panes().size(), 5);
    QCOMPARE(m_page->panes().first()->seriesCount(), 3);
    QCOMPARE(m_page->panes().first()->legendEntries(),
             (QStringList{"P1 tip", "P1 setpoint", "P1 power"}));
    m_page->setPaneLayout(ChartsPage::Layout::Overlaid);
    QCOMPARE(m_page->panes().size(), 2);
}

// Off by default; on, every port gets its transistor curve and the station one transformer
// curve, with the simulator's readings (which follow the power drawn, above ambient).
void TestChartsPage::hardwareTemperaturesAreDrawnOnRequest() {
    auto *hardware = m_page->findChild<QToolButton *>(QStringLiteral("hardwareButton"));
    QVERIFY(hardware);
    QVERIFY(!hardware->isChecked());
    QCOMPARE(stationPane()->legendEntries(),
             (QStringList{"Port 1", "Port 2", "Port 3", "Port 4", "tip", "setpoint", "power"}));
    hardware->click();
    QCOMPARE(stationPane()->seriesCount(), 12 + 4 + 1);
    // A colour per port and a dash per kind: what fits in one row above the plot.
    QCOMPARE(stationPane()->legendEntries().mid(4),
             (QStringList{"tip", "setpoint", "power", "transistor", "transformer"}));
    QStringList names;
    for (const ChartTrace &t : m_page->traces(0))
        names.append(t.name);
    QVERIFY2(names.contains(QStringLiteral("P3 transistor")), qPrintable(names.join(u',')));
    QCOMPARE(names.count(QStringLiteral("transformer")), 1);
    QCOMPARE(m_page->traces(1).size(), 2); // the feeder has neither
    waitForSamples(5);
    m_page->redrawNow();
    for (int i = 12; i < 17; ++i)
        QVERIFY2(stationPane()->pointCount(i) > 0, qPrintable(names.at(i)));
    const QString key = TelemetryRecorder::keyOf(*m_session->station(), 1);
    const model::TelemetryBuffer *b = m_session->telemetry().buffer(key);
    for (const char *series : {"transistor", "transformer"}) {
        const qint32 newest =
            b->samples(b->seriesIndex(QLatin1String(series)), b->firstTime(), b->lastTime() + 1)
                .back()
                .value;
        QVERIFY2(newest >= 30 && newest < 100, series); // °C: a real reading, not a 0 filler
    }
    hardware->click();
    QCOMPARE(stationPane()->seriesCount(), 12);
}

void TestChartsPage::theFeedersSeriesStartAtTheirFirstReadings() {
    model::FeederModel *feeder = m_session->feeder();
    QVERIFY(feeder);
    const model::TelemetryBuffer *b =
        m_session->telemetry().buffer(TelemetryRecorder::keyOf(*feeder, 0));
    QVERIFY(b);
    const model::Parameter *setting = feeder->parameter("SPD");
    QTRY_VERIFY_WITH_TIMEOUT(setting->number() && b->size() >= 5, kDataMs);
    const auto speed = setting->number();
    QVERIFY(*speed > 0);
    // Every speed sample is the setting as read: no 0 recorded while it was still to be read.
    for (const auto &s :
         b->samples(b->seriesIndex(QStringLiteral("speed")), b->firstTime(), b->lastTime() + 1))
        QCOMPARE(s.value, qint32(*speed));
}

void TestChartsPage::theDemoAtWorkShowsAJointsRecoveryAndTheFeederFeeding() {
    m_session->disconnectFromLine();
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    settings.demoActivity = true;
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected, kConnectMs);
    m_session->scheduler().setVisiblePorts(m_session->station(), m_page->visiblePorts());
    // The first joint is 8 s into the session and the demo makes one every 15 s after it. The
    // wait ends at the first recovery the panel shows; on a loaded machine the first joint can be
    // read too sparsely to show its return, so the bound lets two more joints come.
    const int jointMs =
        sim::DemoActivity::kJointOffsetMs + 2 * sim::DemoActivity::kJointEveryMs + 4000;
    QTRY_VERIFY2_WITH_TIMEOUT(m_page->measurementText().contains(QStringLiteral("recovery at ")),
                              qPrintable(m_page->measurementText()), jointMs + kDataMs);
    const model::TelemetryBuffer *feeder =
        m_session->telemetry().buffer(TelemetryRecorder::keyOf(*m_session->feeder(), 0));
    QTRY_VERIFY_WITH_TIMEOUT(feeder->windowStats(feeder->seriesIndex(QStringLiteral("fed")),
                                                 feeder->firstTime(), feeder->lastTime() + 1)
                                     .max > 0,
                             kDataMs);
}

void TestChartsPage::aLongRecordingNameNeverWidensThePage() {
    const int before = m_page->minimumSizeHint().width();
    const QString path = m_dir.filePath(
        QStringLiteral("line-3-station-12-%1.csv").arg(QString(120, QLatin1Char('x'))));
    QCOMPARE(m_page->startRecording(path), QString());
    auto *status = m_page->findChild<QLabel *>(QStringLiteral("sourceLabel"));
    QVERIFY(status);
    // Cut short where it is shown, the whole of it one hover away.
    QTRY_VERIFY2(status->text().contains(QChar(0x2026)), qPrintable(status->text()));
    QCOMPARE(m_page->minimumSizeHint().width(), before);
    QVERIFY2(status->toolTip().endsWith(QFileInfo(path).fileName()), qPrintable(status->toolTip()));
    m_page->stopRecording();
}

TIPSCOPE_TEST_MAIN(TestChartsPage)

} // namespace tst_chartspage
#include "tst_chartspage.moc"
