#include "pages/fleet/fleetpage.h"

#include "pages/fleet/fleettilewidget.h"
#include "widgets/flowlayout.h"

#include "model/workspace/linetile.h"
#include "model/workspace/workspace.h"
#include "plant/plantwatch.h"
#include "plant/remotetile.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHash>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>
#include <functional>

namespace tipscope::gui {

using model::FleetSortKey;

namespace {
constexpr int kTileGap = 8;
}

FleetPage::FleetPage(model::Workspace &workspace, QWidget *parent)
    : QWidget(parent)
    , m_workspace(workspace) {
    m_sort = new QComboBox(this);
    m_sort->addItem(tr("Name"), int(FleetSortKey::Name));
    m_sort->addItem(tr("Line"), int(FleetSortKey::Line));
    m_sort->addItem(tr("State, worst first"), int(FleetSortKey::State));
    auto *sortLabel = new QLabel(tr("Sort by:"), this);
    sortLabel->setBuddy(m_sort);
    m_attention = new QCheckBox(tr("Needs attention only"), this);
    m_summary = new QLabel(this);
    m_empty = new QLabel(this);
    m_empty->setAlignment(Qt::AlignCenter);
    m_empty->setWordWrap(true);
    m_host = new QWidget;
    m_flow = new FlowLayout(m_host);
    m_flow->setSpacing(kTileGap);
    m_flow->setContentsMargins(kTileGap, kTileGap, kTileGap, kTileGap);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_scroll->setWidget(m_host);

    auto *toolbar = new QHBoxLayout;
    toolbar->addWidget(sortLabel);
    toolbar->addWidget(m_sort);
    toolbar->addWidget(m_attention);
    toolbar->addStretch(1);
    toolbar->addWidget(m_summary);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(toolbar);
    layout->addWidget(m_empty);
    layout->addWidget(m_scroll, 1);

    connect(m_sort, &QComboBox::currentIndexChanged, this,
            [this] { setSortKey(FleetSortKey(m_sort->currentData().toInt())); });
    connect(m_attention, &QCheckBox::toggled, this, &FleetPage::setAttentionOnly);
    m_refreshTimer.setSingleShot(true);
    m_refreshTimer.setInterval(kRefreshMs / kRefreshSteps);
    // Hidden, the tiles stay marked and are brought up to date when the page is shown.
    connect(&m_refreshTimer, &QTimer::timeout, this, [this] {
        if (isVisible())
            refreshDirtyFor(kRefreshMs - m_refreshTimer.interval());
    });
    connect(&workspace, &model::Workspace::linesChanged, this, &FleetPage::rebuild);
    connect(&workspace, &model::Workspace::lineDevicesChanged, this, &FleetPage::syncLine);
    rebuild();
}

QList<FleetTileWidget *> FleetPage::shownTiles() const {
    QList<FleetTileWidget *> shown;
    for (FleetTileWidget *tile : m_tiles)
        if (!tile->isHidden())
            shown.append(tile);
    return shown;
}

void FleetPage::setSortKey(FleetSortKey key) {
    m_sortKey = key;
    m_sort->setCurrentIndex(m_sort->findData(int(key)));
    arrange();
}

void FleetPage::setAttentionOnly(bool on) {
    m_attentionOnly = on;
    m_attention->setChecked(on);
    arrange();
}

int FleetPage::columnCount() const {
    const QList<FleetTileWidget *> shown = shownTiles();
    if (shown.isEmpty())
        return 0;
    const int top = shown.first()->y();
    return int(std::count_if(shown.cbegin(), shown.cend(),
                             [top](const FleetTileWidget *t) { return t->y() == top; }));
}

void FleetPage::refreshNow() {
    refreshDirtyFor(0);
}

void FleetPage::refreshDirtyFor(qint64 ms) {
    bool changed = false, waiting = false;
    for (FleetTileWidget *tile : std::as_const(m_tiles)) {
        if (tile->dirtyForMs() >= ms)
            changed |= tile->refresh();
        else
            waiting |= tile->isDirty();
    }
    if (changed)
        arrange();
    if (waiting)
        scheduleRefresh();
}

QString FleetPage::summaryText() const {
    const auto attention = std::count_if(m_tiles.cbegin(), m_tiles.cend(),
                                         [](const auto *t) { return t->shown().needsAttention(); });
    const auto empty = std::count_if(m_tiles.cbegin(), m_tiles.cend(),
                                     [](const auto *t) { return t->shown().lineOnly; });
    const QString devices =
        tr("Devices: %1 · need attention: %2").arg(m_tiles.size() - empty).arg(attention);
    return empty == 0 ? devices : tr("%1 · lines without a device: %2").arg(devices).arg(empty);
}

void FleetPage::showEvent(QShowEvent *event) {
    QWidget::showEvent(event);
    refreshNow();
}

void FleetPage::rebuild() {
    removeTilesIf([this](const FleetTileWidget *tile) {
        return tile->tile().lineIndex() >= m_workspace.count();
    });
    for (int line = 0; line < m_workspace.count(); ++line)
        syncLine(line);
    arrange();
}

// A tile stays as long as its device does, so a line joining the workspace or a device found
// again keeps what the other tiles know (since when their line is down, their last joints).
void FleetPage::syncLine(int line) {
    const QList<model::DeviceModel *> &devices = m_workspace.session(line)->devices();
    // A line's own tile (no device) stands in for its devices until it has some.
    removeTilesIf([line, &devices](const FleetTileWidget *tile) {
        const model::DeviceModel *device = tile->tile().device();
        return tile->tile().lineIndex() == line &&
               (device ? !devices.contains(device) : !devices.isEmpty());
    });
    if (devices.isEmpty() && std::none_of(m_tiles.cbegin(), m_tiles.cend(), [line](const auto *t) {
            return t->tile().lineIndex() == line;
        }))
        addLineTile(line);
    for (model::DeviceModel *device : devices) {
        const bool tiled = std::any_of(m_tiles.cbegin(), m_tiles.cend(), [device](const auto *t) {
            return t->tile().device() == device;
        });
        if (!tiled)
            addTile(line, device);
    }
    arrange();
}

void FleetPage::removeTilesIf(const std::function<bool(const FleetTileWidget *)> &gone) {
    for (auto it = m_tiles.begin(); it != m_tiles.end();) {
        if (!gone(*it)) {
            ++it;
            continue;
        }
        m_flow->removeWidget(*it);
        delete *it;
        it = m_tiles.erase(it);
    }
}

void FleetPage::addTile(int line, model::DeviceModel *device) {
    FleetTileWidget *tile = placeTile(new model::FleetTile(m_workspace, line, *device));
    connect(tile, &FleetTileWidget::activated, this, [this, tile] {
        if (model::DeviceModel *device = tile->tile().device())
            Q_EMIT deviceActivated(tile->tile().lineIndex(), device);
    });
}

void FleetPage::addLineTile(int line) {
    FleetTileWidget *tile = placeTile(new model::LineTile(m_workspace, line));
    connect(tile, &FleetTileWidget::activated, this,
            [this, tile] { Q_EMIT deviceActivated(tile->tile().lineIndex(), nullptr); });
    tile->refresh();
}

void FleetPage::watchPlant(const plant::PlantWatch *watch) {
    if (m_plant)
        disconnect(m_plant, nullptr, this, nullptr);
    removeTilesIf([](const FleetTileWidget *tile) {
        return qobject_cast<const plant::RemoteTile *>(&tile->tile()) != nullptr;
    });
    m_plant = watch;
    if (watch) {
        connect(watch, &plant::PlantWatch::deviceAdded, this, [this](const QString &root) {
            addRemoteTile(root);
            arrange();
        });
        connect(watch, &plant::PlantWatch::cleared, this, [this, watch] { watchPlant(watch); });
        for (const QString &root : watch->roots())
            addRemoteTile(root);
    }
    arrange();
}

void FleetPage::addRemoteTile(const QString &root) {
    FleetTileWidget *tile = placeTile(new plant::RemoteTile(*m_plant, root));
    connect(tile, &FleetTileWidget::activated, this,
            [this, root] { Q_EMIT remoteDeviceActivated(root); });
    tile->refresh();
}

FleetTileWidget *FleetPage::placeTile(model::FleetTileSource *source) {
    auto *tile = new FleetTileWidget(source, m_host);
    connect(tile, &FleetTileWidget::dirtied, this, &FleetPage::scheduleRefresh);
    connect(tile, &FleetTileWidget::latencyMeasured, this, &FleetPage::recordLatency);
    m_flow->addWidget(tile);
    m_flow->setAlignment(tile, Qt::AlignTop);
    m_tiles.append(tile);
    return tile;
}

void FleetPage::scheduleRefresh() {
    if (!m_refreshTimer.isActive())
        m_refreshTimer.start();
}

void FleetPage::arrange() {
    QList<FleetTileWidget *> order = m_tiles;
    std::stable_sort(order.begin(), order.end(), [this](const auto *a, const auto *b) {
        return model::fleetTileBefore(a->shown(), b->shown(), m_sortKey);
    });
    bool moved = order != m_tiles;
    for (FleetTileWidget *tile : std::as_const(order)) {
        const bool show = !m_attentionOnly || tile->shown().needsAttention();
        if (tile->isHidden() == show) {
            tile->setHidden(!show);
            moved = true;
        }
    }
    if (order != m_tiles) {
        // The layout keeps its items; only their order changes.
        QHash<QWidget *, QLayoutItem *> items;
        while (QLayoutItem *item = m_flow->takeAt(0))
            items.insert(item->widget(), item);
        for (FleetTileWidget *tile : std::as_const(order))
            m_flow->addItem(items.value(tile));
        m_tiles = order;
    }
    if (moved)
        m_flow->invalidate();
    m_summary->setText(summaryText());
    const bool none = shownTiles().isEmpty();
    m_empty->setText(!m_tiles.isEmpty() ? tr("No device needs attention.")
                     : m_plant ? tr("No devices yet: nothing has come from the plant's broker.")
                               : tr("No devices: the workspace's lines have found none yet."));
    m_empty->setVisible(none);
}

void FleetPage::recordLatency(double ms) {
    if (m_latencies.size() < kMaxLatencies)
        m_latencies.push_back(ms);
}

} // namespace tipscope::gui
