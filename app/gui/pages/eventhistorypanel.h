// EventHistoryPanel: the Errors page's history: the session's EventLog (errors, alarms, status
// changes, writes, communication errors, connection) with time, severity, kind, source and text,
// filtered by kind, severity and free text. New events arrive through EventLog::appended (and
// new counts of a collapsed flood through EventLog::repeated), are shown in batches at most ten
// times a second, the newest first, and keep the newest row in view unless the reader has
// scrolled down to read. Copy puts the selected rows on the clipboard; exportText() writes the
// rows shown, tab-separated; both in time order, as logs are read. The table is
// model::EventHistoryModel, which any front end can use.
#pragma once

#include "base/outcome.h"
#include "model/events/eventhistorymodel.h"
#include "model/session.h"

#include <QGroupBox>
#include <QHash>
#include <QTimer>

class QComboBox;
class QLabel;
class QLayout;
class QLineEdit;
class QPushButton;
class QTableView;
class QVBoxLayout;

namespace tipscope::gui {

class EventHistoryPanel : public QGroupBox {
    Q_OBJECT
public:
    explicit EventHistoryPanel(model::Session &session, QWidget *parent = nullptr);

    // Copies the selected rows to the clipboard, tab-separated, one event a line.
    void copySelection() const;
    // Writes the rows that pass the filters, with a header line, tab-separated, UTF-8; fails,
    // saying why, when the file cannot be written.
    [[nodiscard]] base::Outcome<void> exportText(const QString &path) const;

private:
    [[nodiscard]] QLayout *buildFilters();
    void buildView(QVBoxLayout &layout);
    void flushEvents();
    void fitTimeColumn();
    void fitSourceColumn(const QList<model::Event> &events);
    void applyFilters();
    void updateCount();
    void updateButtons();
    void chooseExportFile();
    // Offers each device the events name in the device filter, once.
    void addDevices(const QList<model::Event> &events);
    [[nodiscard]] QString rowText(int proxyRow) const;

    model::Session &m_session;
    QComboBox *m_deviceFilter = nullptr;
    QComboBox *m_kindFilter = nullptr;
    QComboBox *m_severityFilter = nullptr;
    QLineEdit *m_textFilter = nullptr;
    QTableView *m_history = nullptr;
    QLabel *m_count = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_copy = nullptr;
    QPushButton *m_export = nullptr;
    model::EventHistoryModel *m_events = nullptr;
    model::EventHistoryFilter *m_filter = nullptr;
    QList<model::Event> m_pending;
    QHash<quint64, model::Event> m_repeats; // by id: rows whose count grew since the last flush
    QTimer m_flush;
    int m_widestSource = 0; // the room the widest source seen needs
};

} // namespace tipscope::gui
