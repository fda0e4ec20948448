// JointsPage: every solder joint, measured and judged, for the engineer who asks "how are the
// joints today" and the support person who asks "what happened at 10:42".
//
// A table of joints, newest first, with the verdict in words, an icon and a tint; the
// temperatures in the session's unit. Under it a histogram of the listed joints' recovery times
// and each tool's daily median recovery. Filters by device, port, tool, verdict, time range and
// work order narrow all three. Export writes the listed joints as CSV (replaced whole or not at
// all). Activating a joint (double-click or Enter) shows the Charts page (setChartsPage()) at
// that moment: chartsShown() asks the main window to bring it to the front; when the charts
// hold no readings of that moment the status line says so.
//
// Where the joints come from: the journal file (setJournalPath(); Journal::defaultPath() until
// told otherwise), read through a JournalReader when the page is built, when a filter changes and
// on reload(), at most kHistoryLimit of the newest; and the session's JointWatcher, live, so the
// table fills even when the journal cannot be written. A joint is listed once whichever way it
// came (JointTableModel keys rows by device, port and start). A journal file that does not exist
// yet is no history, not an error; one that cannot be read says why on the page's status line.
#pragma once

#include "model/joints/jointtable.h"

#include "journal/journaltypes.h"
#include "pages/page.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QTableView;
class QPushButton;

namespace tipscope::gui {

class ChartsPage;
class DeferredRefresh;
class RecoveryHistogramView;
class RecoveryTrendView;

class JointsPage : public Page {
    Q_OBJECT
public:
    static constexpr int kHistoryLimit = 5000;
    // The time ranges the filter offers, in hours back from now; 0: all.
    static constexpr int kRangeHours[] = {1, 24, 7 * 24, 30 * 24, 0};
    static constexpr int kDefaultRange = 2; // the last 7 days

    explicit JointsPage(model::Session &session, QWidget *parent = nullptr);

    [[nodiscard]] QString title() const override { return tr("Joints"); }

    void setJournalPath(const QString &path);
    [[nodiscard]] QString journalPath() const { return m_journalPath; }
    // The work order the journal stamps live joints with, so the table shows it before the
    // journal has them.
    void setWorkOrder(const QString &workOrder) { m_workOrder = workOrder; }
    [[nodiscard]] QString workOrder() const { return m_workOrder; }

    // The filter the widgets say (with the time range from now), as the journal takes it.
    [[nodiscard]] journal::JointFilter filter() const;
    // Sets the filter widgets (the time range by its index in kRangeHours) and reloads.
    void setDeviceFilter(const QString &deviceKey);
    void setPortFilter(int port); // 0: every port
    void setToolFilter(const QString &tool);
    void setVerdictFilter(std::optional<model::JointVerdict> verdict);
    void setRangeFilter(int rangeIndex);
    void setWorkOrderFilter(const QString &workOrder);

    // Reads the journal again and lists what it holds with the live joints that match.
    void reload();
    [[nodiscard]] const model::JointTableModel &table() const { return m_table; }
    [[nodiscard]] QTableView &view() const { return *m_view; }
    [[nodiscard]] QString statusText() const;
    [[nodiscard]] const RecoveryHistogramView &histogramView() const { return *m_histogram; }
    [[nodiscard]] const RecoveryTrendView &trendView() const { return *m_trend; }
    // Brings the histogram and trend up to date with the table (they wait while hidden).
    void flushCharts();
    // Writes the listed joints as CSV; empty on success, else why (also on the status line).
    QString exportCsv(const QString &path);

    void setChartsPage(ChartsPage *charts);
    // The charts at the joint of `row`: empty when shown, else why not (on the status line too).
    QString openJoint(int row);

Q_SIGNALS:
    // The charts page now shows a joint: bring it to the front.
    void chartsShown(QWidget *chartsPage);

private:
    [[nodiscard]] QWidget *buildFilters();
    void onJointEnded(const model::JointRecord &joint);
    void fillDevices(const QList<model::DeviceIdentity> &fromJournal);
    void refreshCharts();
    // The count and what the journal said, on the status line.
    void showCount();
    void showStatus(const QString &text, bool problem);
    void chooseAndExport();

    model::JointTableModel m_table;
    QList<model::JointRow> m_live; // this session's joints, newest last, at most kCapacity
    QString m_journalPath;
    QString m_workOrder;
    QString m_journalProblem; // why the journal could not be read at the last reload
    bool m_hasJournal = false;
    bool m_historyCut = false;
    bool m_otherProblem = false; // a failed export or chart on the status line

    QComboBox *m_deviceBox = nullptr;
    QComboBox *m_portBox = nullptr;
    QLineEdit *m_toolEdit = nullptr;
    QComboBox *m_verdictBox = nullptr;
    QComboBox *m_rangeBox = nullptr;
    QLineEdit *m_workOrderEdit = nullptr;
    QPushButton *m_export = nullptr;
    QLabel *m_status = nullptr;
    QTableView *m_view = nullptr;
    RecoveryHistogramView *m_histogram = nullptr;
    RecoveryTrendView *m_trend = nullptr;
    DeferredRefresh *m_chartsRefresh = nullptr;
    DeferredRefresh *m_widthsRefresh = nullptr;
    QPointer<ChartsPage> m_charts;
};

} // namespace tipscope::gui
