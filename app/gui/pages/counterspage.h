// CountersPage: the usage counters of every connected device, for support staff.
//
// Each station gets a table of its counters (rows: the catalog's "counter" group of a port:
// plugged, work, sleep, hibernation and no-tool hours, sleep and desoldering cycles, then any
// the station has of its own; columns: the ports); each SFR feeder a table of its total and
// partial counters, paired by the quantity they count (plugged hours, feeding hours, fed
// metres), so a counter added to the catalog gets its row. Cells show the parameters' values and
// follow Parameter::valueChanged, so they update whenever the poll scheduler reads a counter;
// refresh() asks the scheduler for every counter now, since counters are otherwise polled
// slowly.
//
// The feeder's partial counters can be reset, each only after a QMessageBox that says what will
// happen (Action::danger()); the model receives Confirmation::Confirmed only when the person
// agreed. In monitor-only mode the resets are disabled and say why. exportCsv() writes every
// counter of every device (device, port, counter, value, unit) for a support ticket.
//
// The page follows Session::devicesChanged and reaches devices only through the session or
// QPointer, so a device that goes away on disconnect never leaves a dangling pointer here.
#pragma once

#include "page.h"

#include "base/outcome.h"

#include <QDateTime>
#include <functional>

class QGroupBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QVBoxLayout;

namespace tipscope::gui {

class DeferredRefresh;

class CountersPage : public Page {
    Q_OBJECT
public:
    explicit CountersPage(model::Session &session, QWidget *parent = nullptr);
    ~CountersPage() override;

    [[nodiscard]] QString title() const override { return tr("Counters"); }
    void setActive(bool active) override;

    // Asks the poll scheduler to read every counter of every device now.
    void refresh();
    // Asks for confirmation, then resets the partial counter with this code (the reset action
    // shares it) of the session's feeder, as its Reset button does.
    void resetPartial(const QByteArray &code);
    // Every counter of every device as CSV (UTF-8, header row "device,port,counter,value,unit",
    // values in display units with a '.' decimal point); fails, saying why, when the file cannot
    // be written.
    [[nodiscard]] base::Outcome<void> exportCsv(const QString &path) const;

private:
    struct ResetButton {
        QPointer<model::FeederModel> feeder;
        QByteArray code;
        QPushButton *button = nullptr;
    };

    void rebuild();
    void addStation(model::StationModel *station);
    void addFeeder(model::FeederModel *feeder);
    [[nodiscard]] QTableWidget *makeTable(const QString &objectName, const QString &accessibleName);
    void bindCell(QTableWidget *table, int row, int column, model::Parameter *parameter);
    void resetPartialOf(model::FeederModel *feeder, const QByteArray &code);
    void updateButtons();
    void noteReading(const QDateTime &when);
    void updateReadAt();
    void showStatus(const QString &text);
    void chooseExportFile();

    QLabel *m_placeholder;
    QVBoxLayout *m_boxLayout;
    QList<QGroupBox *> m_boxes;
    QList<ResetButton> m_resets;
    QPushButton *m_refresh;
    QPushButton *m_export;
    QLabel *m_readAt;
    QLabel *m_status;
    QDateTime m_lastRead;   // the newest reading of any counter shown
    bool m_waiting = false; // a refresh was asked for and nothing has come back yet
    // Parent of every connection to a device's parameters; replaced on each rebuild so that no
    // connection outlives the table cells it writes to.
    QObject *m_bindings = nullptr;
    static constexpr int kReadAtPart = -1;
    QList<std::function<void()>> m_cellUpdates; // a DeferredRefresh part each
    DeferredRefresh *m_deferred = nullptr;      // in m_bindings
};

} // namespace tipscope::gui
