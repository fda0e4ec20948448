// DeviceTree: line -> station (model, address) -> ports (tool); feeder. While a workspace is open
// or a plant is watched, the fleet overview heads the tree (line kFleet, no device). The connection
// bar's line comes first (hidden while a workspace is open and it is not connected), then each line
// of the open workspace under its name, its devices under the names the workspace gives them.
// Selecting an item selects that line, device (and port) on every page. Labels follow the models
// live and are never cut: a long one wraps at its spaces, and each label's tooltip carries its
// whole text.
#pragma once

#include "model/session.h"
#include "model/workspace/workspace.h"

#include <QTimer>
#include <QTreeWidget>

namespace tipscope::gui {

class DeviceTree : public QTreeWidget {
    Q_OBJECT
public:
    // The connection bar's line: line number kBarLine; a workspace line: its index.
    static constexpr int kBarLine = -1;
    // The fleet overview's item: a line number that is no line.
    static constexpr int kFleet = -2;

    DeviceTree(model::Session &session, model::Workspace &workspace, QWidget *parent = nullptr);

    [[nodiscard]] int selectedLine() const;
    [[nodiscard]] model::DeviceModel *selectedDevice() const;
    [[nodiscard]] int selectedPort() const;
    // Selects the device of `line` (and its port when > 0), or the line itself when `device` is
    // null; false when the tree does not hold it.
    bool select(int line, const model::DeviceModel *device, int port = 0);
    // Selects the fleet overview; false while no workspace is open and no plant watched.
    bool selectFleet();
    // The fleet overview also heads the tree while the window watches a plant's broker.
    void setPlantWatched(bool watched);

Q_SIGNALS:
    void selectionChangedTo(int line, tipscope::model::DeviceModel *device, int port);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void rebuild();
    void addLine(int line);
    void relabel();
    void relabelLine(QTreeWidgetItem *lineItem);
    void fitLabels();
    void scheduleRelabel();
    [[nodiscard]] model::Session *sessionOf(int line) const;
    [[nodiscard]] QTreeWidgetItem *lineItem(int line) const;

    static constexpr int kRelabelMs = 250;

    model::Session &m_session;
    model::Workspace &m_workspace;
    QTimer m_relabel;
    bool m_plantWatched = false;
};

} // namespace tipscope::gui
