// ErrorStatePanel: the Errors page's "current state": a row for each station, each of its ports
// and each feeder with the error (and for ports the high/low temperature alarm) at its level (ok,
// info, warning, error, shown as an icon, a word and a tint) and the catalog's plain
// explanation. Below the table, what to check for each error the rows show, in words (the
// catalog's advice), so that nobody has to hover to learn it. The rows follow the error, alarm and
// tool values as the poll scheduler reads them. The feeder's error can be reset
// (FeederModel::resetError(), no confirmation needed: it only clears the code); monitor-only mode
// disables that and says why.
//
// The panel follows Session::devicesChanged and reaches devices only through QPointer, so a
// device that goes away on disconnect never leaves a dangling pointer here.
#pragma once

#include "model/session.h"

#include <QGroupBox>
#include <QMap>
#include <QPointer>

class QLabel;
class QPushButton;
class QScrollArea;
class QTableWidget;

namespace tipscope::gui {

class DeferredRefresh;

class ErrorStatePanel : public QGroupBox {
    Q_OBJECT
public:
    explicit ErrorStatePanel(model::Session &session, QWidget *parent = nullptr);
    ~ErrorStatePanel() override;

    // Clears the error code of the session's feeder, as the Reset button does.
    void resetFeederError();

private:
    struct StateRow {
        QPointer<model::DeviceModel> device;
        int port = 0; // 0: the device's own error
    };

    void rebuild();
    void addRow(model::DeviceModel *device, int port);
    void updateRow(int row);
    void updateButtons();
    void updateAdvice();
    void showStatus(const QString &text);

    model::Session &m_session;
    QTableWidget *m_table = nullptr;
    QPushButton *m_resetFeeder = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_advice = nullptr;
    QScrollArea *m_adviceBox = nullptr; // holds m_advice
    QList<StateRow> m_rows;
    QMap<int, QString> m_rowAdvice; // row -> "where: what to check", for rows in error
    // Parent of every connection to a device's parameters; replaced on each rebuild so that no
    // connection outlives the rows it writes to.
    QObject *m_bindings = nullptr;
    DeferredRefresh *m_refresh = nullptr; // one part per row, in m_bindings
};

} // namespace tipscope::gui
