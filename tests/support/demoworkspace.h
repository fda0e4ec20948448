// Workspaces of in-process demo lines for the fleet tests: each line is the built-in simulated
// DME (at 01) and SFR (at 10), unpaced as in demosession.h, with the names a workspace gives its
// lines and devices. openDemoWorkspace() waits until every line is connected with its station
// and feeder (the workspace polls every port live by itself).
#pragma once

#include "model/workspace/workspace.h"

namespace tipscope::link {
class SimTransport;
}

namespace tipscope::testing {

// A demo line named `name` in `cell`, its station called `station` and its feeder `feeder`.
[[nodiscard]] model::WorkspaceLine demoWorkspaceLine(const QString &name, const QString &cell,
                                                     const QString &station, const QString &feeder);
// False when a line does not connect with its station and feeder within `timeoutMs`.
[[nodiscard]] bool openDemoWorkspace(model::Workspace &workspace,
                                     const QList<model::WorkspaceLine> &lines,
                                     int timeoutMs = 60000);
// The simulated wire of line `index`, to unplug it.
[[nodiscard]] link::SimTransport &demoTransport(model::Workspace &workspace, int index);

} // namespace tipscope::testing
