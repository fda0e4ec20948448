#include "demoworkspace.h"

#include "demosession.h"

#include "link/simtransport.h"

#include <QTest>

namespace tipscope::testing {

model::WorkspaceLine demoWorkspaceLine(const QString &name, const QString &cell,
                                       const QString &station, const QString &feeder) {
    model::WorkspaceLine line;
    line.name = name;
    line.cell = cell;
    line.session = unpacedDemoSettings();
    line.deviceNames = {{1, station}, {10, feeder}};
    return line;
}

bool openDemoWorkspace(model::Workspace &workspace, const QList<model::WorkspaceLine> &lines,
                       int timeoutMs) {
    model::WorkspaceFile file;
    file.lines = lines;
    workspace.open(file);
    return QTest::qWaitFor(
        [&] {
            for (int i = 0; i < workspace.count(); ++i) {
                const model::Session &s = *workspace.session(i);
                if (s.state() != model::Session::State::Connected || !s.station() || !s.feeder())
                    return false;
            }
            return true;
        },
        timeoutMs);
}

link::SimTransport &demoTransport(model::Workspace &workspace, int index) {
    return *qobject_cast<link::SimTransport *>(&workspace.session(index)->line()->transport());
}

} // namespace tipscope::testing
