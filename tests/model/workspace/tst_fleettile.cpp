// FleetTile on a workspace of in-process demo lines: a tile names its device, line and cell as the
// workspace does and shows each port's readings as the port model has them; a port's error is a
// problem of the catalog's level and makes the tile need attention, as a lost line does, which
// says since when by the tile's clock; the last joint's verdict is the port's; tiles sort by
// name as people count, by line, and by state with the worst first.
#include "model/workspace/fleettile.h"
#include "testmain.h"

#include "model/device/stationmodel.h"
#include "model/workspace/workspace.h"

#include "link/simtransport.h"
#include "sim/demoactivity.h"
#include "sim/simline.h"
#include "sim/simstation.h"

#include "demoworkspace.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_fleettile {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::testing::demoTransport;
using tipscope::testing::demoWorkspaceLine;
using tipscope::testing::openDemoWorkspace;

namespace {
constexpr int kConnectMs = 60000;

// Every port of the tile read: tip, setpoint and status.
bool portsRead(const FleetTileState &s) {
    if (s.ports.isEmpty())
        return false;
    for (const FleetPortState &p : s.ports)
        if (!p.tip || !p.setpoint || p.statusText == QStringLiteral("—"))
            return false;
    return true;
}
} // namespace

class TestFleetTile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aTileNamesItsDeviceLineAndCellAndShowsEachPortAsRead();
    void aPortErrorIsAProblemOfItsLevelAndNeedsAttention();
    void aLineDownSaysSinceWhenByTheTilesClock();
    void theLastJointsVerdictIsItsPorts();
    void tilesSortByNameAsPeopleCountByLineAndWorstFirst();
};

void TestFleetTile::aTileNamesItsDeviceLineAndCellAndShowsEachPortAsRead() {
    Workspace workspace;
    QVERIFY(openDemoWorkspace(
        workspace, {demoWorkspaceLine(QStringLiteral("cell-3"), QStringLiteral("North"),
                                      QStringLiteral("Robot 3"), QStringLiteral("Feeder 3"))}));
    Session &session = *workspace.session(0);
    FleetTile station(workspace, 0, *session.station());
    FleetTile feeder(workspace, 0, *session.feeder());
    QTRY_VERIFY_WITH_TIMEOUT(portsRead(station.state()), kConnectMs);
    const FleetTileState s = station.state();
    QCOMPARE(s.deviceName, QStringLiteral("Robot 3"));
    QCOMPARE(s.lineName, QStringLiteral("cell-3"));
    QCOMPARE(s.cell, QStringLiteral("North"));
    QCOMPARE(s.model, session.station()->info().model);
    QVERIFY(s.lineUp && s.lineText.isEmpty() && s.read);
    QCOMPARE(s.ports.size(), session.station()->ports().size());
    QCOMPARE(s.ports.size(), 4);
    for (const FleetPortState &p : s.ports) {
        const PortModel &port = *session.station()->port(p.number);
        QVERIFY(p.tipText.endsWith(QStringLiteral("°C")));
        QCOMPARE(p.setpointText, port.displayText(protocol::Role::Setpoint));
        QCOMPARE(p.toolText, port.toolName());
        QCOMPARE(p.statusText, port.status()->text());
    }
    QVERIFY(s.problems.isEmpty());
    QCOMPARE(s.worst(), Level::Ok);
    QVERIFY(!s.needsAttention());
    QTRY_VERIFY_WITH_TIMEOUT(feeder.state().read, kConnectMs);
    QCOMPARE(feeder.state().deviceName, QStringLiteral("Feeder 3"));
    QVERIFY(feeder.state().ports.isEmpty());
    QVERIFY2(!feeder.state().feederText.isEmpty(), qPrintable(feeder.state().feederText));
}

void TestFleetTile::aPortErrorIsAProblemOfItsLevelAndNeedsAttention() {
    Workspace workspace;
    QVERIFY(openDemoWorkspace(
        workspace, {demoWorkspaceLine(QStringLiteral("a"), {}, QStringLiteral("A"), {}),
                    demoWorkspaceLine(QStringLiteral("b"), {}, QStringLiteral("B"), {})}));
    FleetTile a(workspace, 0, *workspace.session(0)->station());
    FleetTile b(workspace, 1, *workspace.session(1)->station());
    QSignalSpy changed(&a, &FleetTile::changed);
    QVERIFY(changed.isValid());
    QTRY_VERIFY_WITH_TIMEOUT(portsRead(a.state()) && portsRead(b.state()), kConnectMs);
    workspace.session(0)->demoLine()->station()->setPortError(2, 4);
    QTRY_VERIFY_WITH_TIMEOUT(!a.state().problems.isEmpty(), kConnectMs);
    QVERIFY(!changed.isEmpty());
    const PortModel &port = *workspace.session(0)->station()->port(2);
    const FleetProblem problem = a.state().problems.first();
    QCOMPARE(problem.text, QStringLiteral("Port 2: ") + port.errorText());
    QCOMPARE(problem.level, qMax(Level::Warning, port.errorLevel()));
    QVERIFY(a.state().needsAttention());
    QCOMPARE(a.state().worst(), problem.level);
    QVERIFY(b.state().problems.isEmpty());
    QVERIFY(!b.state().needsAttention());
}

void TestFleetTile::aLineDownSaysSinceWhenByTheTilesClock() {
    Workspace workspace;
    QVERIFY(openDemoWorkspace(
        workspace, {demoWorkspaceLine(QStringLiteral("a"), {}, QStringLiteral("A"), {})}));
    const QDateTime at(QDate::currentDate(), QTime(8, 12, 30));
    qint64 now = at.toMSecsSinceEpoch();
    FleetTile tile(workspace, 0, *workspace.session(0)->station(), [&now] { return now; });
    QTRY_VERIFY_WITH_TIMEOUT(portsRead(tile.state()), kConnectMs);
    demoTransport(workspace, 0).setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(!tile.state().lineUp, kConnectMs);
    now += 3600'000; // an hour later the tile still says when it went down
    FleetTileState s = tile.state();
    QCOMPARE(s.downSinceMs, at.toMSecsSinceEpoch());
    QCOMPARE(s.lineText, QStringLiteral("Line down since 08:12"));
    QVERIFY(s.needsAttention());
    QCOMPARE(s.stateRank(), 0);
    now += 24 * 3600'000LL; // the next day it says the date too
    QVERIFY2(tile.state().lineText.size() > s.lineText.size() &&
                 tile.state().lineText.endsWith(QStringLiteral(" 08:12")),
             qPrintable(tile.state().lineText));
    // A tile made while the line is down takes the last reading's time.
    FleetTile late(workspace, 0, *workspace.session(0)->station(), [&now] { return now; });
    QVERIFY(late.state().downSinceMs.has_value());
    QVERIFY(*late.state().downSinceMs <= QDateTime::currentMSecsSinceEpoch());

    demoTransport(workspace, 0).setPlugged(true);
    QTRY_VERIFY_WITH_TIMEOUT(tile.state().lineUp, kConnectMs);
    QVERIFY(tile.state().lineText.isEmpty() && !tile.state().downSinceMs);
    QTRY_VERIFY_WITH_TIMEOUT(!tile.state().needsAttention(), kConnectMs);
}

// The demo station makes a joint on port 1; the tile takes its verdict from the line's watcher.
void TestFleetTile::theLastJointsVerdictIsItsPorts() {
    Workspace workspace;
    WorkspaceLine line =
        demoWorkspaceLine(QStringLiteral("a"), {}, QStringLiteral("A"), QStringLiteral("F"));
    line.session.demoActivity = true;
    QVERIFY(openDemoWorkspace(workspace, {line}));
    FleetTile tile(workspace, 0, *workspace.session(0)->station());
    FleetTile feeder(workspace, 0, *workspace.session(0)->feeder());
    QSignalSpy joints(&workspace.session(0)->joints(), &JointWatcher::jointEnded);
    QVERIFY(joints.isValid());
    QTRY_VERIFY_WITH_TIMEOUT(!joints.isEmpty(), sim::DemoActivity::kJointOffsetMs +
                                                    sim::DemoActivity::kJointEveryMs + 15'000);
    const auto joint = joints.last().at(0).value<JointRecord>();
    const FleetTileState s = tile.state();
    QCOMPARE(s.lastJoint, joint.verdict);
    QCOMPARE(s.lastJointPort, joint.port);
    QCOMPARE(s.ports.at(joint.port - 1).lastJoint, joint.verdict);
    for (const FleetPortState &p : s.ports)
        if (p.number != joint.port)
            QVERIFY(!p.lastJoint);
    QVERIFY(!feeder.state().lastJoint);
}

void TestFleetTile::tilesSortByNameAsPeopleCountByLineAndWorstFirst() {
    Workspace workspace;
    QVERIFY(openDemoWorkspace(
        workspace,
        {demoWorkspaceLine(QStringLiteral("line-b"), {}, QStringLiteral("Robot 10"), {}),
         demoWorkspaceLine(QStringLiteral("line-a"), {}, QStringLiteral("Robot 9"), {}),
         demoWorkspaceLine(QStringLiteral("line-c"), {}, QStringLiteral("Robot 2"), {})}));
    QList<FleetTile *> tiles;
    for (int i = 0; i < workspace.count(); ++i)
        tiles.append(new FleetTile(workspace, i, *workspace.session(i)->station(), {}, this));
    const auto order = [&](FleetSortKey key) {
        QList<FleetTileState> states;
        for (const FleetTile *t : std::as_const(tiles))
            states.append(t->state());
        std::sort(states.begin(), states.end(),
                  [key](const auto &a, const auto &b) { return fleetTileBefore(a, b, key); });
        QStringList names;
        for (const FleetTileState &s : std::as_const(states))
            names.append(s.deviceName);
        return names.join(QLatin1Char(','));
    };
    for (FleetTile *t : std::as_const(tiles))
        QTRY_VERIFY_WITH_TIMEOUT(portsRead(t->state()), kConnectMs);
    QCOMPARE(order(FleetSortKey::Name), QStringLiteral("Robot 2,Robot 9,Robot 10"));
    QCOMPARE(order(FleetSortKey::Line), QStringLiteral("Robot 9,Robot 10,Robot 2"));
    QCOMPARE(order(FleetSortKey::State), QStringLiteral("Robot 2,Robot 9,Robot 10"));
    // Robot 10 in error, Robot 2's line down: the line down first, then the error.
    workspace.session(0)->demoLine()->station()->setPortError(1, 4);
    QTRY_VERIFY_WITH_TIMEOUT(tiles.at(0)->state().worst() >= Level::Warning, kConnectMs);
    demoTransport(workspace, 2).setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(!tiles.at(2)->state().lineUp, kConnectMs);
    QCOMPARE(order(FleetSortKey::State), QStringLiteral("Robot 2,Robot 10,Robot 9"));
    QCOMPARE(order(FleetSortKey::Name), QStringLiteral("Robot 2,Robot 9,Robot 10"));
    qDeleteAll(tiles);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestFleetTile)

} // namespace tst_fleettile
#include "tst_fleettile.moc"
