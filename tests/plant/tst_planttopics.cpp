// Topic names of docs/mqtt.md: the device level from a name or from address and family, every
// level lower-cased and made safe, and the way back from a topic to its site, line and device.
#include "plant/planttopics.h"
#include "testmain.h"

#include <QTest>

namespace tst_planttopics {

using namespace tipscope::plant;

class TestPlantTopics : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void deviceLevels_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("address"); // -1: without addresses
        QTest::addColumn<QString>("family");
        QTest::addColumn<QString>("level");
        QTest::newRow("station at 01") << "" << 1 << "DME"
                                       << "01-dme";
        QTest::newRow("feeder at 10") << "" << 10 << "SFR"
                                      << "10-sfr";
        QTest::newRow("without addresses") << "" << -1 << "DDR"
                                           << "--ddr";
        QTest::newRow("named") << "Rework A" << 1 << "DME"
                               << "rework_a";
        QTest::newRow("named with wildcards") << "Zelle #3/+" << 2 << "HDE"
                                              << "zelle__3__";
        QTest::newRow("umlaut") << "Lötplatz" << 2 << "HDE"
                                << "l_tplatz";
    }
    void deviceLevels() {
        QFETCH(QString, name);
        QFETCH(int, address);
        QFETCH(QString, family);
        QFETCH(QString, level);
        QCOMPARE(
            deviceLevel(name, address < 0 ? std::nullopt : std::optional<int>(address), family),
            level);
    }

    void rootsAreSanitized() {
        QCOMPARE(deviceRoot(QStringLiteral("Plant A"), QStringLiteral("cell-3"),
                            QStringLiteral("01-dme")),
                 QStringLiteral("tipscope/v1/plant_a/cell-3/01-dme"));
        QCOMPARE(deviceRoot(QStringLiteral("site"), QStringLiteral("demo"), QStringLiteral("")),
                 QStringLiteral("tipscope/v1/site/demo/_"));
        QCOMPARE(
            deviceRoot(QStringLiteral("site"), QStringLiteral("_agent"), QStringLiteral("01-dme")),
            QStringLiteral("tipscope/v1/site/__agent/01-dme"));
        QCOMPARE(agentRoot(QStringLiteral("Plant A"), QStringLiteral("tipscope-line-pc")),
                 QStringLiteral("tipscope/v1/plant_a/_agent/tipscope-line-pc"));
    }

    // A device's place: the line's and the workspace's names kept as given (for payloads), its
    // root and presence client made of their safe levels; the agent's own has no line and no
    // presence client of its own.
    void placesAreMadeOfTheSameLevels() {
        const DevicePlace named =
            devicePlace(QStringLiteral("Plant A"), QStringLiteral("pc-7"), QStringLiteral("Cell 3"),
                        QStringLiteral("Rework A"), 1, QStringLiteral("DME"));
        QCOMPARE(named.line, QStringLiteral("Cell 3"));
        QCOMPARE(named.name, QStringLiteral("Rework A"));
        QCOMPARE(named.root, QStringLiteral("tipscope/v1/plant_a/cell_3/rework_a"));
        QCOMPARE(named.client, QStringLiteral("pc-7-cell_3-rework_a"));
        const DevicePlace unnamed =
            devicePlace(QStringLiteral("site"), QStringLiteral("pc-7"), QStringLiteral("cell-3"),
                        QString(), std::nullopt, QStringLiteral("DDR"));
        QCOMPARE(unnamed.root, QStringLiteral("tipscope/v1/site/cell-3/--ddr"));
        QCOMPARE(unnamed.client, QStringLiteral("pc-7-cell-3---ddr"));
        const DevicePlace agent = agentPlace(QStringLiteral("site"), QStringLiteral("pc-7"));
        QCOMPARE(agent.root, agentRoot(QStringLiteral("site"), QStringLiteral("pc-7")));
        QVERIFY(agent.line.isEmpty() && agent.name.isEmpty() && agent.client.isEmpty());
    }

    void topicsParseBack() {
        const auto live =
            parseDeviceTopic(QStringLiteral("tipscope/v1/plant_a/cell-3/01-dme/port/2/live"));
        QVERIFY(live);
        QCOMPARE(live->site, QStringLiteral("plant_a"));
        QCOMPARE(live->line, QStringLiteral("cell-3"));
        QCOMPARE(live->device, QStringLiteral("01-dme"));
        QCOMPARE(live->leaf, QStringLiteral("port/2/live"));
        QVERIFY(!parseDeviceTopic(QStringLiteral("tipscope/v1/plant_a/cell-3/01-dme")));
        QVERIFY(!parseDeviceTopic(QStringLiteral("tipscope/v2/plant_a/cell-3/01-dme/status")));
        QVERIFY(!parseDeviceTopic(QStringLiteral("tipscope/v1/plant_a/_agent/pc/event")));
        QVERIFY(!parseDeviceTopic(QStringLiteral("tipscope/v1/plant_a//01-dme/status")));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestPlantTopics)

} // namespace tst_planttopics
#include "tst_planttopics.moc"
