// The charts' non-widget logic on hand-made telemetry: decimation to points (every column's true
// min and max reach the screen), the crosshair readout, the time window's gestures, and the
// heat-up and recovery measurements.
#include "charts/chartframe.h"
#include "charts/chartviewport.h"
#include "charts/measurementreport.h"
#include "charts/measurements.h"

#include <QSignalSpy>
#include <QTest>
#include <random>

using namespace tipscope;
using namespace tipscope::gui;
using model::TelemetryBuffer;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;
const QStringList kPortSeries = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                 QStringLiteral("power"), QStringLiteral("status")};

// Whether the polyline reaches `value` at `timeMs`: a point there, or a flat stretch at that
// height spanning it (flat runs keep only their ends).
bool reaches(const QList<QPointF> &points, qint64 timeMs, double value) {
    for (qsizetype i = 0; i < points.size(); ++i) {
        if (points.at(i).x() == double(timeMs) && points.at(i).y() == value)
            return true;
        if (i > 0 && points.at(i - 1).y() == value && points.at(i).y() == value &&
            points.at(i - 1).x() <= double(timeMs) && points.at(i).x() >= double(timeMs))
            return true;
    }
    return false;
}
} // namespace

class TestChartsData : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void decimatedPointsKeepEveryColumnsTrueMinAndMax_data();
    void decimatedPointsKeepEveryColumnsTrueMinAndMax();
    void aOneSampleSpikeIsNeverLost();
    void pointsAreInTimeOrderAndLeadInFromTheLeft();
    void readoutIsTheBuffersNewestSampleAtOrBeforeTheInstant();
    void hardwareTemperaturesAreTracedOnlyWhenAskedAndTheTransformerOnce();
    void followingWindowMovesWithTheData();
    void zoomKeepsTheInstantUnderTheCursorAndStopsFollowing();
    void windowLengthStaysBetween30SecondsAnd24Hours();
    void panStopsAtTheData();
    void heatUpRunsFromTheSetpointChangeUntilWithinTheBand();
    void recoveryRunsFromLeavingTheBandUntilBackInIt();
    void restsAndAnUnheatedTipAreNoDips();
    void aWindowReachingBeforeTheDataIsMeasuredFromItsFirstSample();
    void theReportGivesEachSeriesItsWindowStatsThreeToALine();
};

void TestChartsData::decimatedPointsKeepEveryColumnsTrueMinAndMax_data() {
    QTest::addColumn<int>("samples");
    QTest::addColumn<int>("columns");
    QTest::addColumn<int>("seed");
    QTest::newRow("fewer samples than columns") << 300 << 1000 << 1;
    QTest::newRow("ten samples a column") << 10'000 << 1000 << 2;
    QTest::newRow("a day at 1920 columns") << 864'000 << 1920 << 3;
    QTest::newRow("odd columns") << 50'000 << 997 << 4;
}

void TestChartsData::decimatedPointsKeepEveryColumnsTrueMinAndMax() {
    QFETCH(int, samples);
    QFETCH(int, columns);
    QFETCH(int, seed);
    TelemetryBuffer buffer(kPortSeries, samples);
    std::mt19937 random{quint32(seed)};
    std::uniform_int_distribution<int> step(-3, 3);
    QList<qint32> tips;
    qint32 tip = 300;
    for (int i = 0; i < samples; ++i) {
        tip += step(random);
        tips.append(tip);
        buffer.append(kT0 + i * 100, {tip, 350, 0, 0});
    }
    const qint64 t1 = kT0 + qint64(samples) * 100;
    const SeriesFormat format =
        seriesFormat(QStringLiteral("tip"), model::TemperatureUnit::Celsius);
    const QList<QPointF> points = minMaxPoints(buffer, 0, kT0, t1, columns, format);
    QVERIFY(points.size() <= 2 * columns);
    // An independent reference: each column's extremes by reading every sample.
    const qint64 span = t1 - kT0;
    int sample = 0;
    for (int k = 0; k < columns; ++k) {
        const qint64 end = kT0 + span * (k + 1) / columns;
        std::optional<int> minAt, maxAt;
        for (; sample < samples && kT0 + sample * 100 < end; ++sample) {
            if (!minAt || tips.at(sample) < tips.at(*minAt))
                minAt = sample;
            if (!maxAt || tips.at(sample) > tips.at(*maxAt))
                maxAt = sample;
        }
        if (!minAt)
            continue;
        QVERIFY2(reaches(points, kT0 + *minAt * 100, tips.at(*minAt)),
                 qPrintable(QStringLiteral("column %1 lost its minimum").arg(k)));
        QVERIFY2(reaches(points, kT0 + *maxAt * 100, tips.at(*maxAt)),
                 qPrintable(QStringLiteral("column %1 lost its maximum").arg(k)));
    }
}

void TestChartsData::aOneSampleSpikeIsNeverLost() {
    TelemetryBuffer buffer(kPortSeries);
    for (int i = 0; i < 864'000; ++i)
        buffer.append(kT0 + i * 100, {i == 431'999 ? 999 : 350, 350, 0, 0});
    const SeriesFormat f = seriesFormat(QStringLiteral("tip"), model::TemperatureUnit::Fahrenheit);
    ValueSpan span;
    const QList<QPointF> points = minMaxPoints(buffer, 0, kT0, kT0 + 86'400'000, 1920, f, &span);
    QCOMPARE(span.max, f.toDisplay(999));
    QVERIFY(reaches(points, kT0 + 431'999LL * 100, f.toDisplay(999)));
    // A flat day needs a handful of points, not two per column.
    QVERIFY2(points.size() < 10, qPrintable(QString::number(points.size())));
}

void TestChartsData::pointsAreInTimeOrderAndLeadInFromTheLeft() {
    TelemetryBuffer buffer(kPortSeries);
    for (int i = 0; i < 5000; ++i)
        buffer.append(kT0 + i * 100, {qint32((i * 37) % 101), 350, 0, 0});
    const SeriesFormat f = seriesFormat(QStringLiteral("tip"), model::TemperatureUnit::Celsius);
    const qint64 t0 = kT0 + 100'050;
    const QList<QPointF> points = minMaxPoints(buffer, 0, t0, kT0 + 400'000, 333, f);
    QVERIFY(!points.isEmpty());
    QCOMPARE(points.first().x(), double(kT0 + 100'000)); // the sample before the window
    for (qsizetype i = 1; i < points.size(); ++i)
        QVERIFY(points.at(i).x() >= points.at(i - 1).x());
}

void TestChartsData::readoutIsTheBuffersNewestSampleAtOrBeforeTheInstant() {
    model::Telemetry telemetry;
    telemetry.ensureBuffer(QStringLiteral("01/port1"), kPortSeries);
    for (int i = 0; i < 100; ++i)
        telemetry.append(QStringLiteral("01/port1"), kT0 + i * 250, {200 + i, 350, i * 10, 0});
    ChartChannel channel;
    channel.key = QStringLiteral("01/port1");
    channel.port = 1;
    channel.series = kPortSeries;
    const QList<ChartTrace> traces = tracesFor({channel}, {0}, model::TemperatureUnit::Celsius);
    QCOMPARE(traces.size(), 3); // tip, setpoint, power; status is no curve
    const QList<ReadoutValue> at = readoutAt(telemetry, {channel}, traces, kT0 + 2600);
    QCOMPARE(at.at(0).sampleMs, kT0 + 2500);
    QCOMPARE(at.at(0).display, 210.0);
    QCOMPARE(at.at(2).display, 10.0); // 100 per mille is 10 %
    QVERIFY(!readoutAt(telemetry, {channel}, traces, kT0 - 1).at(0).valid);
    QVERIFY(readoutText(traces, at, kT0 + 2600).contains(QStringLiteral("P1 tip 210 °C")));
}

void TestChartsData::hardwareTemperaturesAreTracedOnlyWhenAskedAndTheTransformerOnce() {
    const QStringList series =
        kPortSeries + QStringList{QStringLiteral("transistor"), QStringLiteral("transformer")};
    QList<ChartChannel> channels(2);
    for (int i = 0; i < 2; ++i) {
        channels[i].port = i + 1;
        channels[i].address = QStringLiteral("01");
        channels[i].series = series;
    }
    const auto names = [&channels](model::TemperatureUnit unit, bool hardware) {
        QStringList out;
        for (const ChartTrace &t : tracesFor(channels, {0, 1}, unit, hardware))
            out.append(t.name + QLatin1Char(' ') + t.format.unit);
        return out;
    };
    QCOMPARE(names(model::TemperatureUnit::Celsius, false).size(), 6);
    const QStringList on = names(model::TemperatureUnit::Fahrenheit, true);
    QCOMPARE(on.size(), 6 + 2 + 1);
    QVERIFY(on.contains(QStringLiteral("P1 transistor °F")));
    QVERIFY(on.contains(QStringLiteral("P2 transistor °F")));
    QCOMPARE(on.count(QStringLiteral("transformer °F")), 1);
}

void TestChartsData::followingWindowMovesWithTheData() {
    ChartViewport v;
    QSignalSpy changed(&v, &ChartViewport::changed);
    QVERIFY(changed.isValid());
    v.setDataRange(kT0, kT0 + 600'000);
    QCOMPARE(v.end(), kT0 + 600'001);
    QCOMPARE(v.windowMs(), ChartViewport::kDefaultWindowMs);
    v.setDataRange(kT0, kT0 + 700'000);
    QCOMPARE(v.end(), kT0 + 700'001);
    QCOMPARE(changed.count(), 2);
    v.setFollowing(false);
    v.setDataRange(kT0, kT0 + 800'000);
    QCOMPARE(v.end(), kT0 + 700'001); // paused: the window stays
}

void TestChartsData::zoomKeepsTheInstantUnderTheCursorAndStopsFollowing() {
    ChartViewport v;
    v.setDataRange(kT0, kT0 + 3600'000);
    const qint64 anchor = v.start() + v.windowMs() / 4;
    const double fraction = double(anchor - v.start()) / double(v.windowMs());
    v.zoom(0.5, anchor);
    QVERIFY(!v.isFollowing());
    QCOMPARE(v.windowMs(), ChartViewport::kDefaultWindowMs / 2);
    QVERIFY(qAbs(double(anchor - v.start()) / double(v.windowMs()) - fraction) < 1e-3);
    v.reset();
    QVERIFY(v.isFollowing());
    QCOMPARE(v.windowMs(), ChartViewport::kDefaultWindowMs);
}

void TestChartsData::windowLengthStaysBetween30SecondsAnd24Hours() {
    ChartViewport v;
    v.setDataRange(kT0, kT0 + 48 * 3600'000LL);
    v.zoom(1e-6, v.end());
    QCOMPARE(v.windowMs(), ChartViewport::kMinWindowMs);
    v.zoom(1e6, v.end());
    QCOMPARE(v.windowMs(), ChartViewport::kMaxWindowMs);
    v.showRange(kT0 + 1000, kT0 + 2000); // grows around its middle
    QCOMPARE(v.windowMs(), ChartViewport::kMinWindowMs);
    QCOMPARE(v.start() + v.windowMs() / 2, kT0 + 1500);
}

void TestChartsData::panStopsAtTheData() {
    ChartViewport v;
    v.setDataRange(kT0, kT0 + 3600'000);
    v.pan(-100 * 3600'000LL);
    QVERIFY(!v.isFollowing());
    QVERIFY(v.end() > kT0); // some of the data stays in view
    v.pan(1000 * 3600'000LL);
    QVERIFY(v.start() < kT0 + 3600'000);
}

void TestChartsData::heatUpRunsFromTheSetpointChangeUntilWithinTheBand() {
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

void TestChartsData::recoveryRunsFromLeavingTheBandUntilBackInIt() {
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

void TestChartsData::restsAndAnUnheatedTipAreNoDips() {
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

void TestChartsData::aWindowReachingBeforeTheDataIsMeasuredFromItsFirstSample() {
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

void TestChartsData::theReportGivesEachSeriesItsWindowStatsThreeToALine() {
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

QTEST_GUILESS_MAIN(TestChartsData)
#include "tst_chartsdata.moc"
