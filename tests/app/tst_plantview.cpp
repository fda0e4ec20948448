// The plant view: a window connected to the plant's broker shows on its fleet overview every
// device a real tipscope-agent publishes there (its demo line: a DME and an SFR), with live
// values; a remote tile opens the device's read-only page with its ports, their curves and its
// joints; when the agent dies (kill -9), its tiles and page say the agent is offline instead of
// looking current, and its curves break there.
#include "charts/chartwidget.h"
#include "devicetree.h"
#include "mainwindow.h"
#include "pages/fleet/fleetpage.h"
#include "pages/fleet/fleettilewidget.h"
#include "pages/fleet/remotedevicepage.h"
#include "plant/remotehistory.h"
#include "plant/remotetile.h"
#include "testmain.h"

#include "../mqtt/mqtttesting.h"
#include "../plant/agentprocess.h"
#include "mosquittobroker.h"

#include <QStackedWidget>
#include <QTest>

namespace tst_plantview {

using namespace tipscope;
using namespace tipscope::testing;
using tipscope::gui::FleetTileWidget;

namespace {
FleetTileWidget *tileNamed(gui::FleetPage &page, const QString &model) {
    page.refreshNow();
    for (FleetTileWidget *tile : page.shownTiles())
        if (tile->shown().model == model)
            return tile;
    return nullptr;
}
} // namespace

class TestPlantView : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void theFleetShowsWhatTheAgentsPublish() {
        MosquittoBroker broker;
        TIPSCOPE_START_BROKER(broker);
        AgentProcess agent;
        agent.configure(QStringLiteral("demo"), broker.port());
        QString error;
        QVERIFY2(agent.start(&error), qPrintable(error));

        gui::MainWindow window;
        window.resize(1280, 720);
        window.show();
        mqtt::MqttSettings settings = brokerSettings(broker, QStringLiteral("test-view"));
        window.watchPlant(settings, QStringLiteral("Test Site"));
        gui::FleetPage &fleet = window.fleetPage();
        QCOMPARE(window.shownPages(), &fleet);

        FleetTileWidget *station = nullptr;
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         station = tileNamed(fleet, QStringLiteral("DME-2C"));
                         return station && !station->shown().ports.isEmpty() &&
                                station->shown().ports.first().tip.has_value();
                     },
                     30000),
                 qPrintable(agent.log()));
        QVERIFY(tileNamed(fleet, QStringLiteral("SFR-A")));
        QVERIFY(station->shown().lineUp);
        QCOMPARE(station->shown().lineName, QStringLiteral("cell-1"));
        QCOMPARE(station->shown().ports.size(), 4);
        QVERIFY(station->lines().join('\n').contains(QStringLiteral("°C")));

        // The demo makes a joint on port 1 every 15 s: it reaches the tile and the page.
        QVERIFY(QTest::qWaitFor(
            [&] {
                fleet.refreshNow();
                return station->shown().lastJoint.has_value();
            },
            40000));
        QTest::mouseClick(station, Qt::LeftButton);
        gui::RemoteDevicePage &page = window.remoteDevicePage();
        QCOMPARE(window.shownPages(), &page);
        QVERIFY(QTest::qWaitFor(
            [&] { return page.lines().join('\n').contains(QStringLiteral("current")); }, 5000));
        const QString shown = page.lines().join('\n');
        QVERIFY2(shown.contains(QStringLiteral("DME-2C")), qPrintable(shown));
        QVERIFY2(shown.contains(QStringLiteral("T210")), qPrintable(shown));
        QVERIFY2(!shown.contains(QStringLiteral("not current")), qPrintable(shown));
        // The chart draws the curves received from the live topic: four ports, three curves each.
        QCOMPARE(page.chart().seriesCount(), 12);
        QVERIFY(QTest::qWaitFor([&] { return page.chart().pointCount(0) >= 2; }, 10000));
        const model::TelemetryKey port1 = plant::RemoteHistory::keyOf(page.root(), 1);
        const model::TelemetryBuffer *history = page.history().telemetry().buffer(port1);
        QVERIFY(history && history->size() >= 2);
        QVERIFY(!history->gaps().isOpen());

        // The agent dies: the broker publishes its devices' wills.
        agent.kill();
        QVERIFY(QTest::qWaitFor(
            [&] {
                fleet.refreshNow();
                return !station->shown().lineUp;
            },
            10000));
        // Its curves break where the agent went: nothing after it is joined to what came before.
        QVERIFY(page.history().telemetry().buffer(port1)->gaps().isOpen());
        // Seen going: since when it went.
        QVERIFY2(station->shown().lineText.startsWith(QStringLiteral("Agent offline since")),
                 qPrintable(station->shown().lineText));
        // A window that comes later finds only the retained will, whose time is when the device
        // came online: it says offline, and not since that time.
        plant::PlantWatch later;
        later.start(brokerSettings(broker, QStringLiteral("test-later-view")),
                    QStringLiteral("Test Site"));
        QString root;
        QVERIFY(QTest::qWaitFor(
            [&] {
                for (const QString &r : later.roots())
                    if (later.device(r)->statusKnown && later.device(r)->device == "01-dme")
                        root = r;
                return !root.isEmpty();
            },
            10000));
        QCOMPARE(plant::remoteTileState(*later.device(root), 0).lineText,
                 QStringLiteral("Agent offline"));
        QVERIFY(QTest::qWaitFor(
            [&] { return page.lines().join('\n').contains(QStringLiteral("not current")); }, 5000));

        window.stopWatchingPlant();
        fleet.refreshNow();
        QVERIFY(!tileNamed(fleet, QStringLiteral("DME-2C")));
    }
};

TIPSCOPE_TEST_MAIN(TestPlantView)

} // namespace tst_plantview
#include "tst_plantview.moc"
