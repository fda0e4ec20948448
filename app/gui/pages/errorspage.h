// ErrorsPage: what is wrong now and what went wrong before, for support staff and technicians.
//
// The "current state" table has a row for each station, each of its ports and each feeder:
// the error (and for ports the high/low temperature alarm flags) with its severity (ok, info,
// warning, error, from Catalog::severity() and the family's tables, shown as an icon, a word and
// a tint) and the catalog's plain explanation. The rows follow the error and alarm parameters as
// the poll scheduler reads them. The feeder's error can be reset (FeederModel::resetError(), no
// confirmation needed: it only clears the code); monitor-only mode disables that and says why.
//
// The history table shows the session's EventLog (errors, alarms, status changes, writes,
// communication errors, connection) with time, severity, kind, source and text; it can be
// filtered by kind, severity and free text. New events arrive through EventLog::appended, are
// shown in batches at most ten times a second, and keep the newest row in view unless the reader
// has scrolled up. Copy puts the selected rows on the clipboard; exportText() writes the rows
// shown, tab-separated.
//
// The page follows Session::devicesChanged and reaches devices only through QPointer, so a
// device that goes away on disconnect never leaves a dangling pointer here.
#pragma once

#include "page.h"

#include <QTimer>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;
class QTableWidget;

namespace tipscope::gui {

class DeferredRefresh;
class EventHistoryFilter;
class EventHistoryModel;

class ErrorsPage : public Page {
    Q_OBJECT
public:
    explicit ErrorsPage(model::Session &session, QWidget *parent = nullptr);
    ~ErrorsPage() override;

    [[nodiscard]] QString title() const override { return tr("Errors"); }
    void setActive(bool active) override;

    // Clears the error code of the session's feeder, as the Reset button does.
    void resetFeederError();
    // Copies the selected history rows to the clipboard, tab-separated, one event a line.
    void copySelection() const;
    // Writes the history rows that pass the filters, with a header line, tab-separated, UTF-8.
    // Returns false and sets *error (if given) when the file cannot be written.
    [[nodiscard]] bool exportText(const QString &path, QString *error) const;

private:
    struct StateRow {
        QPointer<model::DeviceModel> device;
        int port = 0; // 0: the device's own error
    };

    QWidget *buildStatePanel();
    QWidget *buildHistoryPanel();
    void rebuildState();
    void addStateRow(model::DeviceModel *device, int port);
    void updateStateRow(int row);
    void updateButtons();
    void showStatus(const QString &text);
    void flushEvents();
    void applyFilters();
    void updateCount();
    void chooseExportFile();
    [[nodiscard]] QString rowText(int proxyRow) const;

    QTableWidget *m_state = nullptr;
    QPushButton *m_resetFeeder = nullptr;
    QLabel *m_status = nullptr;
    QList<StateRow> m_rows;

    QComboBox *m_kindFilter = nullptr;
    QComboBox *m_severityFilter = nullptr;
    QLineEdit *m_textFilter = nullptr;
    QTableView *m_history = nullptr;
    QLabel *m_count = nullptr;
    QLabel *m_historyStatus = nullptr;
    QPushButton *m_copy = nullptr;
    QPushButton *m_export = nullptr;
    EventHistoryModel *m_events = nullptr;
    EventHistoryFilter *m_filter = nullptr;
    QList<model::Event> m_pending;
    QTimer m_flush;

    // Parent of every connection to a device's parameters; replaced on each rebuild so that no
    // connection outlives the rows it writes to.
    QObject *m_bindings = nullptr;
    DeferredRefresh *m_stateRefresh = nullptr; // one part per row, in m_bindings
};

} // namespace tipscope::gui
