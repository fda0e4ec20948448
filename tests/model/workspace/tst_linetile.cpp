// LineTile, the fleet overview's tile for a line without a device, on an in-process demo line:
// it names the line and cell and says the line is not up; pulled, it says since when by its own
// clock and why, at the error level, and keeps that time however long the line stays down; put
// back, the down time is gone. A tile made while its line is down does not guess since when.
#include "model/workspace/linetile.h"
#include "testmain.h"

#include "link/simtransport.h"
#include "model/workspace/workspace.h"

#include "demoworkspace.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_linetile {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::testing::demoTransport;
using tipscope::testing::demoWorkspaceLine;
using tipscope::testing::openDemoWorkspace;

namespace {
constexpr int kConnectMs = 60000;
}

class TestLineTile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aPulledLineSaysSinceWhenAndWhy();
    void aTileMadeWhileTheLineIsDownDoesNotGuessSinceWhen();
};

void TestLineTile::aPulledLineSaysSinceWhenAndWhy() {
    Workspace workspace;
    QVERIFY(openDemoWorkspace(workspace, {demoWorkspaceLine(QStringLiteral("cell-3 line"),
                                                            QStringLiteral("Cell 3"), {}, {})}));
    const QDateTime at(QDate::currentDate(), QTime(8, 12, 30));
    qint64 now = at.toMSecsSinceEpoch();
    LineTile tile(workspace, 0, [&now] { return now; });
    QSignalSpy changed(&tile, &FleetTileSource::changed);
    FleetTileState s = tile.state();
    QCOMPARE(s.lineName, QStringLiteral("cell-3 line"));
    QCOMPARE(s.cell, QStringLiteral("Cell 3"));
    QCOMPARE(s.deviceName, QStringLiteral("No device"));
    QVERIFY(s.lineOnly && !s.lineUp && !s.downSinceMs);

    demoTransport(workspace, 0).setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(tile.state().downSinceMs.has_value(), kConnectMs);
    QVERIFY(!changed.isEmpty());
    now += 3600'000;    // an hour later, tried again and again meanwhile, it still says when
    QTest::qWait(2500); // two attempts to reopen it
    s = tile.state();
    QCOMPARE(*s.downSinceMs, at.toMSecsSinceEpoch());
    QCOMPARE(s.lineText, QStringLiteral("Line down since 08:12"));
    QVERIFY(!s.problems.isEmpty());
    QCOMPARE(s.problems.first().level, Level::Error);
    QVERIFY2(!s.problems.first().text.isEmpty(), "no reason given");
    QVERIFY(s.needsAttention());

    demoTransport(workspace, 0).setPlugged(true);
    QTRY_VERIFY_WITH_TIMEOUT(!tile.state().downSinceMs, kConnectMs);
    QVERIFY2(!tile.state().lineText.startsWith(QStringLiteral("Line down")),
             qPrintable(tile.state().lineText));
}

void TestLineTile::aTileMadeWhileTheLineIsDownDoesNotGuessSinceWhen() {
    Workspace workspace;
    QVERIFY(openDemoWorkspace(workspace, {demoWorkspaceLine(QStringLiteral("a"), {}, {}, {})}));
    demoTransport(workspace, 0).setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(workspace.session(0)->state() != Session::State::Connected,
                             kConnectMs);
    const LineTile tile(workspace, 0, [] { return qint64(0); });
    const FleetTileState s = tile.state();
    QVERIFY(!s.downSinceMs);
    QVERIFY(!s.problems.isEmpty());
    QCOMPARE(s.problems.first().level, Level::Error);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestLineTile)

} // namespace tst_linetile

#include "tst_linetile.moc"
