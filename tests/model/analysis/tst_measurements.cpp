// The measurements of a tip curve on hand-made telemetry: heat-ups from a setpoint change or a
// wake, recoveries from a joint's dip (rests and an unheated tip are none), and the measurement
// report's window statistics.
#include "model/analysis/measurementreport.h"
#include "model/analysis/measurements.h"
#include "testmain.h"

#include <QTest>

namespace tst_measurements {

using namespace tipscope;
using namespace tipscope::model;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;
const QStringList kPortSeries = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                 QStringLiteral("power"), QStringLiteral("status")};
} // namespace

class TestMeasurements : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void heatUpRunsFromTheSetpointChangeUntilWithinTheBand();
    void aHeatUpFlaggedLateRunsFromWhereTheTipBeganToClimb_data();
    void aHeatUpFlaggedLateRunsFromWhereTheTipBeganToClimb();
    void recoveryRunsFromLeavingTheBandUntilBackInIt();
    void noMeasurementSpansAGap();
    void restsAndAnUnheatedTipAreNoDips();
    void aWindowReachingBeforeTheDataIsMeasuredFromItsFirstSample();
    void theReportGivesEachSeriesItsWindowStatsThreeToALine();
};

void TestMeasurements::heatUpRunsFromTheSetpointChangeUntilWithinTheBand() {
    TelemetryBuffer b(kPortSeries);
    qint32 tip = 300;
    for (int i = 0; i < 600; ++i) { // 60 s: at 10 s the setpoint goes 300 -> 350, +1 °C a tick
        const qint32 setpoint = i < 100 ? 300 : 350;
        if (i >= 100 && tip < 350)
            ++tip;
        b.append(kT0 + i * 100, {tip, setpoint, 500, 0});
    }
    const PortMeasurements m = Measurements::measurePort(b, kT0, kT0 + 60'000, 5);
    QCOMPARE(m.heatUps.size(), 1);
    QCOMPARE(m.heatUps.first().startMs, kT0 + 10'000);
    QCOMPARE(m.heatUps.first().target, 350);
    QVERIFY(m.heatUps.first().reachedMs);
    QCOMPARE(*m.heatUps.first().reachedMs - m.heatUps.first().startMs, 4400); // 345 at tick 144
    QVERIFY(m.recoveries.isEmpty());
}

void TestMeasurements::aHeatUpFlaggedLateRunsFromWhereTheTipBeganToClimb_data() {
    QTest::addColumn<bool>("wake");
    QTest::addColumn<qint64>("flagMs"); // when the new status or setpoint was read
    QTest::newRow("a wake read 6 s late") << true << qint64(16'000);
    QTest::newRow("a wake read at once") << true << qint64(10'100);
    QTest::newRow("a new setpoint read 7 s late") << false << qint64(17'000);
}

// A tip waking from sleep at 150 °C (or asked for 350 instead of 300) starts to climb at 10 s, at
// 50 °C a second, with a ±1 °C wobble before; the status (or setpoint) that says so is read
// later, as a station's slow values are. The heat-up runs from the climb's first step all the
// same, and reaches the band (345 °C) when the tip does, whenever the flag came.
void TestMeasurements::aHeatUpFlaggedLateRunsFromWhereTheTipBeganToClimb() {
    QFETCH(bool, wake);
    QFETCH(qint64, flagMs);
    const qint32 from = wake ? 150 : 300;
    const qint32 sleep = 2;
    TelemetryBuffer b(kPortSeries);
    for (qint64 t = 0; t < 30'000; t += 100) {
        const qint32 wobble = t % 300 == 0 ? 1 : t % 300 == 100 ? -1 : 0;
        const qint32 tip =
            t < 10'000 ? from + wobble : qMin<qint32>(350, from + qint32((t - 10'000) / 20));
        const bool flagged = t >= flagMs;
        b.append(kT0 + t, {tip, !wake && !flagged ? 300 : 350, tip < 345 ? 1000 : 300,
                           wake && !flagged ? sleep : 0});
    }
    const PortMeasurements m = Measurements::measurePort(b, kT0, kT0 + 30'000, 5);
    QCOMPARE(m.heatUps.size(), 1);
    const HeatUp &h = m.heatUps.first();
    QCOMPARE(h.wake, wake);
    // The climb's foot is the last sample before it: 10 s, or a wobble's low sample just before.
    QVERIFY2(h.startMs >= kT0 + 9'800 && h.startMs <= kT0 + 10'000,
             qPrintable(QString::number(h.startMs - kT0)));
    QVERIFY(h.reachedMs);
    QCOMPARE(*h.reachedMs, kT0 + 10'000 + (345 - from) * 20);
    QVERIFY(m.recoveries.isEmpty());
}

void TestMeasurements::noMeasurementSpansAGap() {
    TelemetryBuffer b(kPortSeries);
    // A heat-up to 350 starts at 10 s; the line goes down at 12 s, before the tip is in the
    // band, and is back 25 s later with the tip long there; a joint dips at 50 s and the line
    // goes down again in the middle of it.
    qint32 tip = 300;
    for (int i = 0; i < 120; ++i) {
        const qint32 setpoint = i < 100 ? 300 : 350;
        if (i >= 100 && tip < 350)
            ++tip;
        b.append(kT0 + i * 100, {tip, setpoint, 500, 0});
    }
    b.markGap(kT0 + 12'000, TelemetryGap::Cause::LineDown);
    for (int i = 370; i < 520; ++i)
        b.append(kT0 + i * 100, {i >= 500 ? 320 : 350, 350, 500, 0});
    b.markGap(kT0 + 52'000, TelemetryGap::Cause::NoAnswer);
    for (int i = 800; i < 900; ++i)
        b.append(kT0 + i * 100, {350, 350, 200, 0});
    const PortMeasurements m = Measurements::measurePort(b, kT0, kT0 + 90'000, 5);
    QCOMPARE(m.heatUps.size(), 1);
    QCOMPARE(m.heatUps.first().startMs, kT0 + 10'000);
    QVERIFY2(!m.heatUps.first().reachedMs, "the heat-up ended unseen, in the gap");
    QCOMPARE(m.recoveries.size(), 1);
    QCOMPARE(m.recoveries.first().startMs, kT0 + 50'000);
    QVERIFY2(!m.recoveries.first().recoveredMs, "the recovery ended unseen, in the gap");
}

void TestMeasurements::recoveryRunsFromLeavingTheBandUntilBackInIt() {
    TelemetryBuffer b(kPortSeries);
    for (int i = 0; i < 3000; ++i) { // a joint at 100 s draws the tip down to 320 for 2 s
        const bool dip = i >= 1000 && i < 1020;
        b.append(kT0 + i * 100, {dip ? 320 : 350, 350, dip ? 1000 : 200, 0});
    }
    const PortMeasurements m = Measurements::measurePort(b, kT0, kT0 + 300'000, 5);
    QCOMPARE(m.recoveries.size(), 1);
    const Recovery &r = m.recoveries.first();
    QCOMPARE(r.startMs, kT0 + 100'000);
    QCOMPARE(r.lowest, 320);
    QVERIFY(r.recoveredMs);
    QCOMPARE(*r.recoveredMs - r.startMs, 2000);
}

void TestMeasurements::restsAndAnUnheatedTipAreNoDips() {
    TelemetryBuffer b(kPortSeries);
    for (int i = 0; i < 3000; ++i) {
        const bool stand = i >= 500 && i < 1500;   // cools in the stand: a rest, no dip
        const bool noTool = i >= 2000 && i < 2500; // cools with no power at all
        const qint32 tip = stand || noTool ? 200 : 350;
        b.append(kT0 + i * 100, {tip, 350, noTool ? 0 : 300, stand ? 1 : 0});
    }
    const PortMeasurements m = Measurements::measurePort(b, kT0, kT0 + 300'000, 5);
    QVERIFY(m.recoveries.isEmpty());
    QCOMPARE(m.heatUps.size(), 0); // stand -> working is no wake: the tip never slept
    // The session records 0 until the setpoint is read: no heat-up "from 0".
    TelemetryBuffer fresh(kPortSeries);
    for (int i = 0; i < 100; ++i)
        fresh.append(kT0 + i * 100, {25 + 3 * i, i < 10 ? 0 : 350, 1000, 0});
    QVERIFY(Measurements::measurePort(fresh, kT0, kT0 + 10'000, 5).heatUps.isEmpty());
    // A tool pulled while working: the first samples of the fall still carry full power.
    TelemetryBuffer pulled(kPortSeries);
    for (int i = 0; i < 600; ++i) {
        const bool gone = i >= 300;
        pulled.append(kT0 + i * 100, {gone ? qMax(25, 350 - (i - 299) * 5) : 350, 350,
                                      gone && i > 302 ? 0
                                      : gone          ? 1000
                                                      : 400,
                                      0});
    }
    QVERIFY(Measurements::measurePort(pulled, kT0, kT0 + 60'000, 5).recoveries.isEmpty());
    // But a joint whose first sample still carries the idle power of a tip just above its
    // setpoint (0: power and tip are read one after the other) is a dip all the same.
    TelemetryBuffer joint(kPortSeries);
    for (int i = 0; i < 300; ++i) {
        const bool dip = i >= 100 && i < 110;
        joint.append(kT0 + i * 100, {dip ? 330 - (i == 105 ? 10 : 0) : 352, 350,
                                     i == 100 ? 0
                                     : dip    ? 1000
                                              : 0,
                                     0});
    }
    QCOMPARE(Measurements::measurePort(joint, kT0, kT0 + 30'000, 5).recoveries.size(), 1);
}

void TestMeasurements::aWindowReachingBeforeTheDataIsMeasuredFromItsFirstSample() {
    // A session 2 minutes old seen through a 5-minute window: the window starts 3 minutes
    // before the first sample, and the joint at 60 s must still be found.
    TelemetryBuffer b(kPortSeries);
    for (int i = 0; i < 1200; ++i) {
        const bool dip = i >= 600 && i < 610;
        b.append(kT0 + i * 100, {dip ? 320 : 350, 350, dip ? 1000 : 200, 0});
    }
    const PortMeasurements m = Measurements::measurePort(b, kT0 - 180'000, kT0 + 120'000, 5);
    QCOMPARE(m.recoveries.size(), 1);
    QCOMPARE(m.recoveries.first().startMs, kT0 + 60'000);
    QCOMPARE(*m.recoveries.first().recoveredMs - m.recoveries.first().startMs, 1000);
    QVERIFY(m.heatUps.isEmpty()); // the first sample is no setpoint change
    // A window wholly before the data measures nothing.
    const PortMeasurements none = Measurements::measurePort(b, kT0 - 60'000, kT0 - 1, 5);
    QVERIFY(none.recoveries.isEmpty() && none.heatUps.isEmpty());
}

void TestMeasurements::theReportGivesEachSeriesItsWindowStatsThreeToALine() {
    const QStringList series =
        kPortSeries + QStringList{QStringLiteral("transistor"), QStringLiteral("transformer")};
    model::Telemetry telemetry;
    ChartChannel port1;
    port1.key = QStringLiteral("01/port1");
    port1.port = 1;
    port1.title = QStringLiteral("Port 1");
    port1.address = QStringLiteral("01");
    port1.series = series;
    ChartChannel port2 = port1;
    port2.key = QStringLiteral("01/port2");
    port2.port = 2;
    port2.title = QStringLiteral("Port 2");
    ChartChannel unrecorded = port1;
    unrecorded.key = QStringLiteral("01/port4");
    ChartChannel idle = port1;
    idle.key = QStringLiteral("01/port3");
    idle.title = QStringLiteral("Port 3");
    for (const ChartChannel &c : {port1, port2, idle})
        telemetry.ensureBuffer(c.key, series);
    for (int i = 0; i < 100; ++i) { // the tips stay within the band: no dips to list
        telemetry.append(port1.key, kT0 + i * 100, {346 + i % 9, 350, 100 + i, 0, 40 + i / 10, 55});
        telemetry.append(port2.key, kT0 + i * 100, {350, 350, 50, 0, 45, 55});
    }
    MeasurementRequest request;
    request.t0 = kT0;
    request.t1 = kT0 + 10'000;
    const QList<ChartChannel> channels{port1, port2, unrecorded, idle};

    const QString port1Line = QStringLiteral("Port 1 — Tip: min 346 °C, max 354 °C, mean 350.0 °C; "
                                             "Setpoint: min 350 °C, max 350 °C, mean 350.0 °C; "
                                             "Power: min 10.0 %, max 19.9 %, mean 14.95 %");
    const QString port2Line = QStringLiteral("Port 2 — Tip: min 350 °C, max 350 °C, mean 350.0 °C; "
                                             "Setpoint: min 350 °C, max 350 °C, mean 350.0 °C; "
                                             "Power: min 5.0 %, max 5.0 %, mean 5.00 %");
    const QString idleLine = QStringLiteral("Port 3: no samples in this window");
    QCOMPARE(measurementReport(telemetry, channels, request).split(QLatin1Char('\n')),
             (QStringList{port1Line, port2Line, idleLine}));

    // With the hardware curves drawn, their stats too: the transformer once for the station.
    request.hardware = true;
    QCOMPARE(measurementReport(telemetry, channels, request).split(QLatin1Char('\n')),
             (QStringList{port1Line,
                          QStringLiteral("    Transistor: min 40 °C, max 49 °C, mean 44.5 °C; "
                                         "Transformer: min 55 °C, max 55 °C, mean 55.0 °C"),
                          port2Line,
                          QStringLiteral("    Transistor: min 45 °C, max 45 °C, mean 45.0 °C"),
                          idleLine}));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestMeasurements)

} // namespace tst_measurements
#include "tst_measurements.moc"
