// FleetPage: the fleet overview: every device of every line of a Workspace as a tile
// (FleetTileWidget), and every device of a watched plant's broker (plant::RemoteTile), in rows
// that wrap, so a narrow window shows one column and a wall display
// many. A toolbar sorts the tiles by name, line or state (the worst first) and can show only the
// devices that need attention (FleetTileState::needsAttention()). Clicking a tile (or Enter on
// it) is deviceActivated(), for the window to open that device's own pages. A line without a
// device has a tile of its own (model::LineTile) saying why, until its devices are found; its
// click is deviceActivated() with no device, for the window to open the line.
//
// Readings arrive far faster than anyone reads 128 ports: a tile only notes that it may have
// changed, and the page refreshes a tile kRefreshMs at most after it noted it, so only tiles whose
// state changed repaint, and then re-sorts or re-filters if a change moved one. The page looks
// kRefreshSteps times per kRefreshMs and takes the tiles whose time is nearly up: all tiles at
// once painted for milliseconds in one go, and every line's answer that came meanwhile waited,
// which cost a fleet of 32 lines a tenth of its wire. The tiles follow
// the workspace: its lines opened, added or closed, a line's devices found again; a tile lives as
// long as its device. The page polls nothing itself: the workspace polls every port of a fleet.
//
// For the fleet benchmark: how late each tile repaint came after the tip reading that caused it
// (tileLatenciesMs(), in ms, at most kMaxLatencies kept).
#pragma once

#include "model/workspace/fleettile.h"

#include <QTimer>
#include <QWidget>
#include <functional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QScrollArea;

namespace tipscope::model {
class DeviceModel;
class Workspace;
} // namespace tipscope::model

namespace tipscope::plant {
class PlantWatch;
}

namespace tipscope::gui {

class FlowLayout;
class FleetTileWidget;

class FleetPage : public QWidget {
    Q_OBJECT
public:
    static constexpr int kRefreshMs = 150;
    static constexpr int kRefreshSteps = 4;
    static constexpr size_t kMaxLatencies = 1'000'000;

    explicit FleetPage(model::Workspace &workspace, QWidget *parent = nullptr);

    [[nodiscard]] QString title() const { return tr("Fleet"); }
    [[nodiscard]] int tileCount() const { return int(m_tiles.size()); }
    // The tiles shown, in their order (the filter applied).
    [[nodiscard]] QList<FleetTileWidget *> shownTiles() const;
    void setSortKey(model::FleetSortKey key);
    [[nodiscard]] model::FleetSortKey sortKey() const { return m_sortKey; }
    void setAttentionOnly(bool on);
    [[nodiscard]] bool attentionOnly() const { return m_attentionOnly; }
    // The tiles side by side in the first row, as laid out now.
    [[nodiscard]] int columnCount() const;
    // Refreshes every tile that may have changed now, without waiting for the timer.
    void refreshNow();
    // Refreshes the tiles dirty for at least `ms`; keeps the timer going while others are dirty.
    void refreshDirtyFor(qint64 ms);
    // Also shows every device the plant's broker publishes (none: only the workspace's). The
    // watch must outlive the page or be replaced first.
    void watchPlant(const plant::PlantWatch *watch);
    // The summary above the tiles ("Devices: 8 · need attention: 2").
    [[nodiscard]] QString summaryText() const;

    [[nodiscard]] std::vector<double> tileLatenciesMs() const { return m_latencies; }
    void clearTileLatencies() { m_latencies.clear(); }

Q_SIGNALS:
    // `device` is null for a line's own tile.
    void deviceActivated(int line, tipscope::model::DeviceModel *device);
    // A tile of a device another TipScope publishes: its topic root.
    void remoteDeviceActivated(const QString &root);

protected:
    void showEvent(QShowEvent *event) override;

private:
    void rebuild();
    void syncLine(int line);
    void removeTilesIf(const std::function<bool(const FleetTileWidget *)> &gone);
    void addTile(int line, model::DeviceModel *device);
    void addLineTile(int line);
    void addRemoteTile(const QString &root);
    FleetTileWidget *placeTile(model::FleetTileSource *source);
    void scheduleRefresh();
    // Puts the tiles in order and applies the filter; relays them out only if that moved one.
    void arrange();
    void recordLatency(double ms);

    model::Workspace &m_workspace;
    const plant::PlantWatch *m_plant = nullptr;
    QComboBox *m_sort;
    QCheckBox *m_attention;
    QLabel *m_summary;
    QLabel *m_empty;
    QScrollArea *m_scroll;
    QWidget *m_host;
    FlowLayout *m_flow;
    QList<FleetTileWidget *> m_tiles; // in the order laid out
    QTimer m_refreshTimer;
    model::FleetSortKey m_sortKey = model::FleetSortKey::Name;
    bool m_attentionOnly = false;
    std::vector<double> m_latencies;
};

} // namespace tipscope::gui
