// The joint detector on readings made by hand, as a port's poll would deliver them: a joint's
// start, recovery, depth and power are measured to within the poll period and judged against
// the limits; heat-ups, wakes and early dips are no joints; a gap, a pulled tool or the heater
// going off end a joint as incomplete.
#include "model/joints/jointdetector.h"

#include <QTest>

using namespace tipscope::model;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;
constexpr int kSetpoint = 350;
constexpr qint64 kPollMs = 100;
constexpr qint64 kDropMs = 300;

// A joint at `startMs`: the tip falls linearly by `dip` K over kDropMs and climbs back over
// `climbMs`, the power at 80 % while the tip is low. Before and after: the setpoint, 10 %.
struct Curve {
    qint64 startMs;
    int dip;
    qint64 climbMs;

    [[nodiscard]] double tipAt(qint64 t) const {
        const qint64 d = t - startMs;
        if (d <= 0 || d >= kDropMs + climbMs)
            return kSetpoint;
        if (d < kDropMs)
            return kSetpoint - dip * double(d) / kDropMs;
        return kSetpoint - dip * (1 - double(d - kDropMs) / double(climbMs));
    }
    [[nodiscard]] double powerAt(qint64 t) const { return tipAt(t) < kSetpoint ? 80 : 10; }
    // When the tip leaves and re-enters the 5 K band.
    [[nodiscard]] qint64 leaves(int band) const { return startMs + kDropMs * band / dip; }
    [[nodiscard]] qint64 returns(int band) const {
        return startMs + kDropMs + qint64(double(climbMs) * (1 - double(band) / dip));
    }
};

PortReading reading(qint64 t, double tip, double power = 10, QString tool = QStringLiteral("C245"),
                    bool working = true) {
    return {t, int(std::lround(tip)), kSetpoint, power, working, tool};
}

// Feeds the curve from `from` to `to` every kPollMs; the joints that ended.
QList<JointRecord> feed(JointDetector &d, const Curve &c, qint64 from, qint64 to) {
    QList<JointRecord> out;
    for (qint64 t = from; t < to; t += kPollMs)
        if (const auto j = d.add(reading(t, c.tipAt(t), c.powerAt(t))))
            out.append(*j);
    return out;
}
} // namespace

class TestJointDetector : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aJointIsMeasuredToWithinThePollPeriod();
    void theVerdictFollowsTheLimits_data();
    void theVerdictFollowsTheLimits();
    void heatUpsWakesAndEarlyDipsAreNoJoints();
    void whatBreaksTheMeasurementEndsTheJointIncomplete_data();
    void whatBreaksTheMeasurementEndsTheJointIncomplete();
    void aJointThatNeverRecoversEndsAfterTheGiveUpTime();
    void aSteepDropIsTimedAtTheMiddleOfItsIntervalAGentleOneByItsLine();
};

void TestJointDetector::aJointIsMeasuredToWithinThePollPeriod() {
    DeviceIdentity device;
    device.model = QStringLiteral("DME-2C");
    device.line = QStringLiteral("/dev/ttyUSB0");
    device.address = 1;
    JointDetector d(device, 2);
    const Curve c{kT0 + 5037, 50, 1200};
    const QList<JointRecord> joints = feed(d, c, kT0, kT0 + 10'000);
    QCOMPARE(joints.size(), 1);
    const JointRecord &j = joints.first();
    QCOMPARE(j.device, device);
    QCOMPARE(j.port, 2);
    QCOMPARE(j.tool, QStringLiteral("C245"));
    QCOMPARE(j.setpoint, kSetpoint);
    QVERIFY2(std::abs(j.startMs - c.leaves(5)) <= kPollMs / 2,
             qPrintable(QStringLiteral("%1 vs %2").arg(j.startMs).arg(c.leaves(5))));
    QVERIFY(j.recoveryMs.has_value());
    const qint64 truth = c.returns(5) - c.leaves(5);
    QVERIFY2(std::abs(*j.recoveryMs - truth) <= kPollMs / 2,
             qPrintable(QStringLiteral("%1 ms vs %2 ms").arg(*j.recoveryMs).arg(truth)));
    QCOMPARE(j.endMs, j.startMs + *j.recoveryMs);
    QCOMPARE(j.durationMs, *j.recoveryMs);
    // The bottom is seen as deep as the readings around it went: never deeper, and short of
    // it by at most what the tip falls in one poll.
    QVERIFY2(j.dipDepth <= 50 && j.dipDepth >= 50 - 50 * kPollMs / kDropMs,
             qPrintable(QString::number(j.dipDepth)));
    QCOMPARE(j.lowestTip, kSetpoint - j.dipDepth);
    QCOMPARE(j.powerPeak, 80);
    // 80 % for the time the tip was out of the band, give or take a poll at each end.
    const double expected = 80.0 * double(truth) / 1000;
    QVERIFY2(std::abs(j.powerIntegral - expected) <= 80.0 * 2 * kPollMs / 1000,
             qPrintable(QStringLiteral("%1 %·s vs %2").arg(j.powerIntegral).arg(expected)));
    QCOMPARE(j.verdict, JointVerdict::Ok);
}

void TestJointDetector::theVerdictFollowsTheLimits_data() {
    QTest::addColumn<int>("dip");
    QTest::addColumn<qint64>("climbMs");
    QTest::addColumn<JointVerdict>("verdict");
    QTest::newRow("shallow and quick") << 30 << qint64(1000) << JointVerdict::Ok;
    QTest::newRow("slow") << 30 << qint64(4000) << JointVerdict::SlowRecovery;
    QTest::newRow("deep") << 120 << qint64(1000) << JointVerdict::TooDeep;
    QTest::newRow("deep and slow: the depth is said")
        << 120 << qint64(6000) << JointVerdict::TooDeep;
}

void TestJointDetector::theVerdictFollowsTheLimits() {
    QFETCH(int, dip);
    QFETCH(qint64, climbMs);
    QFETCH(JointVerdict, verdict);
    JointDetector d({}, 1, JointLimits{5, 3000, 80});
    const QList<JointRecord> joints = feed(d, Curve{kT0 + 5000, dip, climbMs}, kT0, kT0 + 20'000);
    QCOMPARE(joints.size(), 1);
    QCOMPARE(joints.first().verdict, verdict);
}

void TestJointDetector::heatUpsWakesAndEarlyDipsAreNoJoints() {
    JointDetector d({}, 1);
    qint64 t = kT0;
    // A heat-up from cold: the tip climbs into the band, never falls out of it.
    for (double tip = 25; tip < kSetpoint; tip += 20, t += kPollMs)
        QVERIFY(!d.add(reading(t, tip, 100)));
    // A dip before the tip settled for two seconds (the heat-up's overshoot and dip back).
    QVERIFY(!d.add(reading(t += kPollMs, kSetpoint)));
    QVERIFY(!d.add(reading(t += kPollMs, kSetpoint - 20, 60)));
    QVERIFY(!d.add(reading(t += kPollMs, kSetpoint)));
    // Sleep at 200 °C, then a wake: the climb back is not a recovery.
    for (int i = 0; i < 30; ++i)
        QVERIFY(!d.add(reading(t += kPollMs, 200, 0, QStringLiteral("C245"), false)));
    for (double tip = 200; tip <= kSetpoint; tip += 10)
        QVERIFY(!d.add(reading(t += kPollMs, tip, 100)));
    QVERIFY(!d.inJoint());
    // Settled at last, a dip is a joint.
    for (int i = 0; i < 25; ++i)
        QVERIFY(!d.add(reading(t += kPollMs, kSetpoint)));
    QVERIFY(!d.add(reading(t += kPollMs, kSetpoint - 30, 80)));
    QVERIFY(d.inJoint());
}

void TestJointDetector::whatBreaksTheMeasurementEndsTheJointIncomplete_data() {
    QTest::addColumn<QString>("cause");
    QTest::newRow("a gap in the readings") << QStringLiteral("gap");
    QTest::newRow("a reading without a tip") << QStringLiteral("no answer");
    QTest::newRow("the tool pulled") << QStringLiteral("tool");
    QTest::newRow("the heater off") << QStringLiteral("off");
}

void TestJointDetector::whatBreaksTheMeasurementEndsTheJointIncomplete() {
    QFETCH(QString, cause);
    JointDetector d({}, 1);
    const Curve c{kT0 + 5000, 60, 2000};
    QVERIFY(feed(d, c, kT0, kT0 + 5500).isEmpty());
    QVERIFY(d.inJoint());
    const qint64 t = kT0 + 5600;
    std::optional<JointRecord> j;
    if (cause == QLatin1String("gap"))
        j = d.gap(t);
    else if (cause == QLatin1String("no answer"))
        j = d.add(PortReading{t, std::nullopt, kSetpoint, 80, true, QStringLiteral("C245")});
    else if (cause == QLatin1String("tool"))
        j = d.add(reading(t, 200, 0, QString()));
    else
        j = d.add(reading(t, c.tipAt(t), 0, QStringLiteral("C245"), false));
    QVERIFY(j.has_value());
    QCOMPARE(j->verdict, JointVerdict::Incomplete);
    QVERIFY(!j->recoveryMs.has_value());
    QVERIFY(j->endMs >= j->startMs);
    QVERIFY(!d.inJoint());
    // And the port settles again before another joint counts: the rest of this dip is none.
    QVERIFY(feed(d, c, t + kPollMs, kT0 + 9000).isEmpty());
}

void TestJointDetector::aJointThatNeverRecoversEndsAfterTheGiveUpTime() {
    JointDetector d({}, 1);
    qint64 t = kT0;
    for (; t < kT0 + 3000; t += kPollMs)
        QVERIFY(!d.add(reading(t, kSetpoint)));
    std::optional<JointRecord> j;
    for (; !j && t < kT0 + 3000 + 2 * JointDetector::kGiveUpMs; t += kPollMs)
        j = d.add(reading(t, kSetpoint - 40, 100));
    QVERIFY(j.has_value());
    QCOMPARE(j->verdict, JointVerdict::SlowRecovery);
    QVERIFY(!j->recoveryMs.has_value());
    QVERIFY(j->durationMs > JointDetector::kGiveUpMs);
}

// A settled tip read at 0 and then far below at 100 left the band at an unknown moment between:
// a straight line from the flat reading would say 13 ms, too early for a drop that is steep
// from wherever it began, so the middle (50 ms) is taken. A tip 7 K below at 100 slid out
// gently, and the straight line's 79 ms stands.
void TestJointDetector::aSteepDropIsTimedAtTheMiddleOfItsIntervalAGentleOneByItsLine() {
    const auto startOf = [](int below) {
        JointDetector d(DeviceIdentity{}, 1);
        for (qint64 t = 0; t <= 2000; t += kPollMs)
            (void)d.add(reading(kT0 + t, kSetpoint));
        (void)d.add(reading(kT0 + 2100, kSetpoint - below, 80));
        (void)d.add(reading(kT0 + 2200, kSetpoint - below, 80));
        const auto j = d.add(reading(kT0 + 2300, kSetpoint, 10));
        return j ? j->startMs - (kT0 + 2000) : qint64(-1);
    };
    QCOMPARE(startOf(40), 50); // steep: the middle of the interval
    QCOMPARE(startOf(7), 79);  // gentle: 5.5 / 7 of the way
}

QTEST_GUILESS_MAIN(TestJointDetector)
#include "tst_jointdetector.moc"
