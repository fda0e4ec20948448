// portEvents(): every port's heat-ups, wakes and recoveries over a span, one list in time order
// (ports in order at the same instant), each naming its channel, with its target and a
// recovery's lowest tip; a feeder's channel and a channel without a history have none. The words
// for each kind are the same in every language. On hand-made telemetry.
#include "model/analysis/portevents.h"
#include "testmain.h"

#include <QTest>

namespace tst_portevents {

using namespace tipscope;
using namespace tipscope::model;

namespace {

constexpr qint64 kT0 = 1'700'000'000'000;
const QStringList kPortSeries = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                 QStringLiteral("power"), QStringLiteral("status")};

ChartChannel channel(const QString &key, int port) {
    ChartChannel c;
    c.key = key;
    c.id = port == 0 ? QStringLiteral("feeder") : QStringLiteral("port%1").arg(port);
    c.port = port;
    c.series = port == 0 ? QStringList{QStringLiteral("length")} : kPortSeries;
    return c;
}

// 30 s of a port read every 100 ms: settled at 350 °C, then what `at(t)` makes of it.
void record(Telemetry &telemetry, const QString &key,
            const std::function<QList<qint32>(qint64 t)> &at) {
    (void)telemetry.ensureBuffer(key, kPortSeries);
    for (qint64 t = 0; t < 30'000; t += 100)
        (void)telemetry.append(key, kT0 + t, at(t));
}

} // namespace

class TestPortEvents : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyPortsEventsInTimeOrder();
    void theKindsHaveWordsForData();
};

void TestPortEvents::everyPortsEventsInTimeOrder() {
    Telemetry telemetry;
    // Port 1 wakes from sleep at 150 °C at 12 s and climbs 50 °C a second.
    record(telemetry, QStringLiteral("p1"), [](qint64 t) -> QList<qint32> {
        if (t < 12'000)
            return {150, 350, 0, 2};
        return {qMin<qint32>(350, 150 + qint32((t - 12'000) / 20)), 350, 1000, 0};
    });
    // Port 2: a joint at 5 s, 40 °C deep, back 2 s later; a second one at 12 s, 20 °C deep.
    record(telemetry, QStringLiteral("p2"), [](qint64 t) -> QList<qint32> {
        const auto dip = [t](qint64 start, qint32 depth) -> qint32 {
            if (t < start || t >= start + 2000)
                return 0;
            const qint64 into = t - start;
            return into < 500 ? qint32(depth * into / 500) : qint32(depth * (2000 - into) / 1500);
        };
        return {350 - dip(5000, 40) - dip(12'000, 20), 350, 300, 0};
    });
    (void)telemetry.ensureBuffer(QStringLiteral("feeder"), {QStringLiteral("length")});
    const QList<ChartChannel> channels{
        channel(QStringLiteral("p1"), 1), channel(QStringLiteral("p2"), 2),
        channel(QStringLiteral("feeder"), 0), channel(QStringLiteral("no history"), 3)};

    const QList<PortEvent> events = portEvents(telemetry, channels, kT0, kT0 + 30'000, 5);
    QStringList seen;
    for (const PortEvent &e : events)
        seen << QStringLiteral("%1 %2 %3")
                    .arg(e.channel, PortEvent::kindToken(e.kind))
                    .arg((e.startMs - kT0) / 1000);
    QCOMPARE(seen, (QStringList{QStringLiteral("port2 recovery 5"), QStringLiteral("port1 wake 12"),
                                QStringLiteral("port2 recovery 12")}));
    const PortEvent &first = events.at(0);
    QCOMPARE(first.port, 2);
    QCOMPARE(first.target, 350);
    QVERIFY(first.lowest && *first.lowest <= 312 && *first.lowest >= 310);
    QVERIFY(first.endMs && *first.endMs > first.startMs);
    const PortEvent &wake = events.at(1);
    QCOMPARE(wake.port, 1);
    QVERIFY(!wake.lowest);
    QVERIFY(wake.endMs); // reached the band: 345 °C at 15.9 s
    QCOMPARE(*wake.endMs - kT0, 15'900);

    // Over a span that ends before the wake reached the band: it is open, not made up.
    const QList<PortEvent> cut = portEvents(telemetry, channels, kT0, kT0 + 13'000, 5);
    QCOMPARE(cut.size(), 3);
    QVERIFY(!cut.at(1).endMs);
}

void TestPortEvents::theKindsHaveWordsForData() {
    QCOMPARE(PortEvent::kindToken(PortEvent::Kind::HeatUp), QStringLiteral("heat-up"));
    QCOMPARE(PortEvent::kindToken(PortEvent::Kind::Wake), QStringLiteral("wake"));
    QCOMPARE(PortEvent::kindToken(PortEvent::Kind::Recovery), QStringLiteral("recovery"));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestPortEvents)

} // namespace tst_portevents

#include "tst_portevents.moc"
