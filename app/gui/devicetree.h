// DeviceTree: line -> station (model, address) -> ports (tool); feeder. Selecting an item
// selects that device (and port) on every page. Labels follow the models live and are never cut:
// a long one wraps at its spaces, and each label's tooltip carries its whole text.
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

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void rebuild();
    void relabel();
    void fitLabels();

    static constexpr int kRelabelMs = 250;

    model::Session &m_session;
    QTimer m_relabel;
};

} // namespace tipscope::gui
