// DeviceTree: line -> station (model, address) -> ports (tool); feeder. Selecting an item
// selects that device (and port) on every page. Labels follow the models live.
#pragma once

#include "model/session.h"

#include <QTimer>
#include <QTreeWidget>

namespace tipscope::gui {

class DeviceTree : public QTreeWidget {
    Q_OBJECT
public:
    explicit DeviceTree(model::Session &session, QWidget *parent = nullptr);

    [[nodiscard]] model::DeviceModel *selectedDevice() const;
    [[nodiscard]] int selectedPort() const;

Q_SIGNALS:
    void selectionChangedTo(tipscope::model::DeviceModel *device, int port);

private:
    void rebuild();
    void relabel();

    static constexpr int kRelabelMs = 250;

    model::Session &m_session;
    QTimer m_relabel;
};

} // namespace tipscope::gui
