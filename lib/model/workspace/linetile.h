// LineTile: the fleet overview's tile for a workspace line that has no device, so a line that
// never came up (a device server switched off, a wrong port, robot mode off) is on the overview
// and needs attention instead of being missing from it. It says what the line's Session says:
// connecting, looking for devices, down since when and why, or up with no device answering.
// A view drops it once the line has devices; their own tiles take over.
#pragma once

#include "model/session.h"
#include "model/workspace/fleettile.h"

namespace tipscope::model {

class LineTile : public FleetTileSource {
    Q_OBJECT
public:
    using Clock = FleetTile::Clock;

    // `clock`: none is the system's.
    LineTile(const Workspace &workspace, int line, Clock clock = {}, QObject *parent = nullptr);

    [[nodiscard]] int lineIndex() const override { return m_line; }
    [[nodiscard]] FleetTileState state() const override;

private:
    void onStateChanged(int line, Session::State state);

    const Workspace &m_workspace;
    int m_line;
    Clock m_clock;
    std::optional<qint64> m_downSinceMs;
};

} // namespace tipscope::model
