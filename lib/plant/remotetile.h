// RemoteTile: a device another TipScope publishes to the plant's broker, as a fleet overview tile
// (model::FleetTileState), from what a PlantWatch keeps of it: the names its agent gives it, its
// model, each port's live values, the feeder, the errors and alarms in force, the last joint.
//
// A device is only current while its agent is online and its line up: an agent gone offline (a
// clean stop or its last will) shows the tile as down, "Agent offline since 08:12", its values
// the last it published; a line its agent cannot reach, as the local tile shows it. Values are
// shown in °C, as published.
#pragma once

#include "plantwatch.h"

#include "model/workspace/fleettile.h"

namespace tipscope::plant {

class RemoteTile : public model::FleetTileSource {
    Q_OBJECT
public:
    // `watch` must outlive the tile.
    RemoteTile(const PlantWatch &watch, QString root, QObject *parent = nullptr);

    [[nodiscard]] QString root() const { return m_root; }
    [[nodiscard]] model::FleetTileState state() const override;

private:
    const PlantWatch &m_watch;
    QString m_root;
};

// The tile's state from what was published about one device; `nowMs` dates "since" texts.
[[nodiscard]] model::FleetTileState remoteTileState(const RemoteDevice &device, qint64 nowMs);

} // namespace tipscope::plant
