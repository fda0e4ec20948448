// PlantWatch against a hostile publisher on a real Mosquitto (issue 38): one retained info of
// 200,000 ports added about 200 MB to a watching window, and nothing bounded the devices, lines
// or strings a broker could hold. What a publisher may declare is bounded (plantwatchlimits.h);
// the rest is refused, logged once per publisher, line or site however often it comes, and a
// good device beside the hostile ones is watched as ever.
#include "../mqtt/mqtttesting.h"
#include "testmain.h"

#include "plant/plantwatch.h"
#include "plant/plantwatchlimits.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>

namespace tst_plantwatch {

using namespace tipscope;
using namespace tipscope::testing;
using L = plant::PlantWatchLimits;

namespace {

QStringList g_refusals; // what tipscope.plant.watch warned

void keepRefusals(QtMsgType type, const QMessageLogContext &context, const QString &message) {
    if (type == QtWarningMsg && qstrcmp(context.category, "tipscope.plant.watch") == 0)
        g_refusals.append(message);
}

QByteArray json(const QJsonObject &o) {
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

QByteArray infoWithPorts(int ports) {
    QJsonArray list;
    for (int p = 1; p <= ports; ++p)
        list.append(QJsonObject{{QStringLiteral("port"), p}, {QStringLiteral("tool"), "T245"}});
    return json(
        {{QStringLiteral("name"), QStringLiteral("hostile")}, {QStringLiteral("ports"), list}});
}

int refusalsNaming(const QString &who) {
    int n = 0;
    for (const QString &r : std::as_const(g_refusals))
        n += r.startsWith(who + QStringLiteral(" refused")) ? 1 : 0;
    return n;
}

} // namespace

class TestPlantWatch : public QObject {
    Q_OBJECT

    MosquittoBroker m_broker;
    mqtt::MqttClient m_publisher;

    // The hostile messages (kept in tests/fuzz/corpus/plantpayload for the fuzz target too).
    QList<QPair<QString, QByteArray>> hostile() const {
        const QString plant = QStringLiteral("tipscope/v1/plant/");
        return {
            {plant + "cell-1/02-dme/info", infoWithPorts(200000)}, // 6 MB
            {plant + "cell-1/03-dme/info", infoWithPorts(L::kMaxPorts + 1)},
            {plant + "cell-1/04-dme/info",
             json({{QStringLiteral("name"), QString(100 * 1024, QLatin1Char('n'))}})},
            {plant + "cell-1/01-dme/port/999/live", json({{QStringLiteral("tip"), 350}})},
            {plant + "cell-1/01-dme/joint",
             json({{QStringLiteral("id"), QString(3000, QLatin1Char('j'))}})},
        };
    }

    void publish(const QString &topic, const QByteArray &payload, bool retain = true) {
        QVERIFY(m_publisher.publish(topic, payload, 1, retain).ok());
    }

private Q_SLOTS:
    void initTestCase() {
        TIPSCOPE_START_BROKER(m_broker);
        QVERIFY(connectClient(m_publisher, brokerSettings(m_broker, QStringLiteral("hostile"))));
    }

    void whatAPublisherMayDeclareIsBoundedAndSaidOnce() {
        const QString plant = QStringLiteral("tipscope/v1/plant/");
        publish(plant + "cell-1/01-dme/info",
                json({{QStringLiteral("name"), QStringLiteral("good")},
                      {QStringLiteral("ports"), QJsonArray{QJsonObject{{"port", 1}}}}}));
        for (const auto &[topic, payload] : hostile())
            publish(topic, payload);
        // More devices on one line, and more lines in one site, than a watcher keeps.
        for (int i = 0; i < L::kMaxDevicesPerLine + 6; ++i)
            publish(plant + QStringLiteral("cell-2/%1-dme/status").arg(i + 10),
                    json({{QStringLiteral("online"), true}}));
        for (int i = 0; i < L::kMaxLinesPerSite + 6; ++i)
            publish(QStringLiteral("tipscope/v1/plant2/line-%1/01-dme/status").arg(i),
                    json({{QStringLiteral("online"), true}}));
        QVERIFY(QTest::qWaitFor([this] { return m_publisher.pendingCount() == 0; }, 20000));

        qInstallMessageHandler(keepRefusals);
        plant::PlantWatch watch;
        watch.start(brokerSettings(m_broker, QStringLiteral("watcher")), QString());
        const int expected = 1 + L::kMaxDevicesPerLine + L::kMaxLinesPerSite;
        QVERIFY2(QTest::qWaitFor([&] { return watch.roots().size() == expected; }, 20000),
                 qPrintable(QString::number(watch.roots().size())));
        // Each again, live: refused again, not said again. Then a last good message, which
        // arrives after them.
        for (const auto &[topic, payload] : hostile())
            publish(topic, payload, false);
        publish(plant + "cell-1/01-dme/status", json({{QStringLiteral("online"), true}}), false);
        QVERIFY(QTest::qWaitFor([&] { return watch.device(plant + "cell-1/01-dme")->statusKnown; },
                                10000));
        qInstallMessageHandler(nullptr);

        const plant::RemoteDevice *good = watch.device(plant + "cell-1/01-dme");
        QCOMPARE(good->info.value(QStringLiteral("name")).toString(), QStringLiteral("good"));
        QVERIFY(good->live.isEmpty());
        QVERIFY(good->joints.isEmpty());
        for (const char *refused : {"02-dme", "03-dme", "04-dme"})
            QVERIFY(!watch.device(plant + "cell-1/" + refused));
        QCOMPARE(watch.roots().size(), expected);
        const QString all = g_refusals.join(QLatin1Char('\n'));
        for (const QString &who :
             {plant + "cell-1/02-dme", plant + "cell-1/03-dme", plant + "cell-1/04-dme",
              plant + "cell-1/01-dme", QStringLiteral("line plant/cell-2"),
              QStringLiteral("site plant2")})
            QVERIFY2(refusalsNaming(who) == 1, qPrintable(who + QStringLiteral(":\n") + all));
        QCOMPARE(g_refusals.size(), 6); // 01-dme's joint and port 999 are one publisher
        QVERIFY2(all.size() < 6 * 300, qPrintable(all.left(2000)));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestPlantWatch)

} // namespace tst_plantwatch
#include "tst_plantwatch.moc"
