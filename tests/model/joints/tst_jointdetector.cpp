// The joint detector on readings made by hand, as a port's poll would deliver them: a joint's
// start, recovery, depth and power are measured to within the poll period and judged against
// the limits; heat-ups, wakes and early dips are no joints; a gap, a pulled tool or the heater
// going off end a joint as incomplete.
#include "model/joints/jointdetector.h"
#include "testmain.h"

#include <QTest>
#include <functional>

namespace tst_jointdetector {

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

// Feeds steady readings within the band every `spacingMs` after `t` until the detector reports
// the joint whose return it has confirmed (it gathers readings after the return for its fit, for
// no longer than JointDetector::kMaxTailMs).
std::optional<JointRecord> afterReturn(JointDetector &d, qint64 t, qint64 spacingMs) {
    for (const qint64 until = t + JointDetector::kMaxTailMs + spacingMs; t <= until;) {
        if (auto j = d.add(reading(t += spacingMs, kSetpoint, 10)))
            return j;
    }
    return std::nullopt;
}

// Feeds the curve from `from` to `to` every kPollMs; the joints that ended.
QList<JointRecord> feed(JointDetector &d, const Curve &c, qint64 from, qint64 to) {
    QList<JointRecord> out;
    for (qint64 t = from; t < to; t += kPollMs)
        if (const auto j = d.add(reading(t, c.tipAt(t), c.powerAt(t))))
            out.append(*j);
    return out;
}

// A joint beginning 4 s in, its tip `below(ms since the joint began)` K under the setpoint, read
// every 60 to 110 ms in whole degrees on a tip wobbling ±1.2 K in a 1.7 s swing with a ripple on
// it, at `phase` of the wobble; the heater at `powerPct` while the tip is low.
constexpr qint64 kWobblingJointMs = 4000;
std::optional<JointRecord> wobblingJoint(const std::function<double(double)> &below, double phase,
                                         double powerPct) {
    const qint64 spacings[] = {60, 95, 70, 110, 80, 65, 100, 75, 90};
    JointDetector d({}, 1);
    std::optional<JointRecord> j;
    size_t k = 0;
    for (qint64 t = kT0; t < kT0 + 12'000 && !j; t += spacings[k++ % std::size(spacings)]) {
        const double s = double(t - kT0) / 1000;
        const double wobble = 1.2 * std::sin(s * 2 * M_PI / 1.7 + phase) +
                              0.4 * std::sin(s * 2 * M_PI / 0.23 + 2 * phase);
        const double low = below(double(t - kT0 - kWobblingJointMs));
        j = d.add(reading(t, kSetpoint - low + wobble, low > 1 ? powerPct : 10));
    }
    return j;
}

// The recovery errors of one joint at eight phases of the wobble: the worst of those measured
// (not bounded), every one within what its record says.
struct RecoveryErrors {
    double worstMeasuredMs = 0;
    bool allHeld = true;
    QString all;

    void add(const JointRecord &j, double trueRecoveryMs) {
        const double error = double(*j.recoveryMs) - trueRecoveryMs;
        all += QStringLiteral(" %1%2").arg(error, 0, 'f', 0).arg(j.recoveryBounded ? "b" : "");
        if (!j.recoveryBounded)
            worstMeasuredMs = qMax(worstMeasuredMs, std::abs(error));
        allHeld = allHeld && std::abs(error) <= double(j.recoveryUncertaintyMs);
    }
};
constexpr double kWobblePhases[] = {0.0, 0.8, 1.6, 2.4, 3.2, 4.0, 4.8, 5.6};
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
    void jointsThatFollowEachOtherWithinASecondAreEachFound();
    void aWobbleJustBeyondTheBandIsNoJoint();
    void aSlowReturnOnAWobblingTipIsBoundedAndTheBoundHolds_data();
    void aSlowReturnOnAWobblingTipIsBoundedAndTheBoundHolds();
    void aJointRightAfterAnOvershootIsFound();
    void aTipThatFallsWhileTheHeaterIdlesIsNoJoint();
    void aReadingBackInTheBandByWobbleDoesNotEndTheJoint();
    void aSlowRecoveryIsPlacedFinerThanTheSpacingAndTheWholeDegrees();
    void aDeepSlowReturnOnAWobblingTipIsPlacedByItsWholeClimb();
    void aStraightReturnOnAWobblingTipIsPlacedByItsWholeClimb_data();
    void aStraightReturnOnAWobblingTipIsPlacedByItsWholeClimb();
    void aReturnTheFitAndTheReadingsDisagreeOnReachesAcrossBoth();
    void theDipIsGivenWithAnIntervalThatHoldsIt_data();
    void theDipIsGivenWithAnIntervalThatHoldsIt();
    void aRecoveryBetweenReadingsFarApartIsBoundedAndJudgedOnlyWhereTheBoundsAllow_data();
    void aRecoveryBetweenReadingsFarApartIsBoundedAndJudgedOnlyWhereTheBoundsAllow();
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
    // The joint keeps the limits it was judged by, for the journal and the board's record.
    QVERIFY(joints.first().limits == JudgedLimits({5, 3000, 80}));
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
// from wherever it began, so the middle (50 ms) is taken. A tip 9 K below at 100 slid out
// gently, and the straight line's 61 ms stands.
void TestJointDetector::aSteepDropIsTimedAtTheMiddleOfItsIntervalAGentleOneByItsLine() {
    const auto startOf = [](int below) {
        JointDetector d(DeviceIdentity{}, 1);
        for (qint64 t = 0; t <= 2000; t += kPollMs)
            (void)d.add(reading(kT0 + t, kSetpoint));
        (void)d.add(reading(kT0 + 2100, kSetpoint - below, 80));
        (void)d.add(reading(kT0 + 2200, kSetpoint - below, 80));
        (void)d.add(reading(kT0 + 2300, kSetpoint, 10));
        (void)d.add(reading(kT0 + 2400, kSetpoint, 10)); // the return confirmed
        const auto j = afterReturn(d, kT0 + 2400, kPollMs);
        return j ? j->startMs - (kT0 + 2000) : qint64(-1);
    };
    QCOMPARE(startOf(40), 50); // steep: the middle of the interval
    QCOMPARE(startOf(9), 61);  // gentle: 5.5 / 9 of the way
}

// A noisy tip at the band's edge reads a degree or two beyond it now and then, settled or just
// back from a joint: not a joint. One reading 3 K beyond the band is the shallowest joint.
void TestJointDetector::aWobbleJustBeyondTheBandIsNoJoint() {
    JointDetector d({}, 1);
    qint64 t = kT0;
    QList<JointRecord> found;
    const auto add = [&](int below, double power) {
        if (const auto j = d.add(reading(t, kSetpoint - below, power)))
            found.append(*j);
        t += kPollMs;
    };
    for (; t < kT0 + 3000;)
        add(0, 10);
    for (const int below : {4, 7, 5, 4, 3, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0})
        add(below, 30);
    QCOMPARE(found.size(), 0);
    for (const int below : {8, 6, 4, 3, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0})
        add(below, 60);
    QCOMPARE(found.size(), 1);
    QVERIFY(found.first().dipDepth >= 8);
}

void TestJointDetector::aSlowReturnOnAWobblingTipIsBoundedAndTheBoundHolds_data() {
    QTest::addColumn<double>("wobbleK");
    QTest::addColumn<bool>("bounded");
    QTest::newRow("quiet tip: measured") << 0.0 << false;
    QTest::newRow("tip wobbling ±1 K: bounded") << 1.0 << true;
}

// A shallow joint (15 K) that comes back along a straight line at 2 K/s: on a quiet tip its
// return is measured to within the stated uncertainty; on a tip that wobbles ±1 K with a 2 s
// swing (as slow as the return itself, which no fit across a few readings can tell from the
// curve) it can only be bounded, and the interval holds the true return. The settled tip's
// wobble before the joint says how far any reading may be off.
void TestJointDetector::aSlowReturnOnAWobblingTipIsBoundedAndTheBoundHolds() {
    QFETCH(double, wobbleK);
    QFETCH(bool, bounded);
    for (const double phase : {0.0, 1.1, 2.3, 3.9, 5.0}) {
        JointDetector d({}, 1);
        const qint64 begin = kT0 + 5000;
        const auto below = [&](qint64 t) {
            const double ms = double(t - begin);
            if (ms <= 0)
                return 0.0;
            if (ms < 300)
                return 15 * ms / 300;
            return qMax(0.0, 15 - 2 * (ms - 300) / 1000);
        };
        std::optional<JointRecord> j;
        for (qint64 t = kT0; t < begin + 12'000 && !j; t += 120) {
            const double wobble = wobbleK * std::sin(double(t) / 1000 * 3.1 + phase);
            j = d.add(reading(t, kSetpoint - below(t) + wobble, below(t) > 0 ? 60 : 10));
        }
        QVERIFY(j && j->recoveryMs);
        const double trueRecovery = (300 + (15 - 5.5) / 2 * 1000) - 15.0 * 5.5 / 15 / 15 * 300;
        const QString got = QStringLiteral("%1 ± %2 ms%3, true %4")
                                .arg(*j->recoveryMs)
                                .arg(j->recoveryUncertaintyMs)
                                .arg(j->recoveryBounded ? QStringLiteral(" bounded") : QString())
                                .arg(trueRecovery);
        QVERIFY2(j->recoveryBounded == bounded, qPrintable(got));
        QVERIFY2(std::abs(double(*j->recoveryMs) - trueRecovery) <=
                     double(j->recoveryUncertaintyMs) + 1,
                 qPrintable(got));
    }
}

// The second joint begins 0.8 s after the first is back within the band: no settling between.
void TestJointDetector::jointsThatFollowEachOtherWithinASecondAreEachFound() {
    JointDetector d({}, 1);
    const Curve first{kT0 + 5000, 40, 900};
    const Curve second{first.returns(5) + 800, 60, 1100};
    QList<JointRecord> joints = feed(d, first, kT0, second.startMs);
    joints += feed(d, second, second.startMs, kT0 + 12'000);
    QCOMPARE(joints.size(), 2);
    QVERIFY(std::abs(joints.at(0).startMs - first.leaves(5)) <= kPollMs / 2);
    QVERIFY(std::abs(joints.at(1).startMs - second.leaves(5)) <= kPollMs / 2);
    QCOMPARE(joints.at(1).verdict, JointVerdict::Ok);
}

// The heater overshoots its return, a reading above the band, and the next joint begins half a
// second later: it is found, as the tip is as settled as before the overshoot.
void TestJointDetector::aJointRightAfterAnOvershootIsFound() {
    JointDetector d({}, 1);
    const Curve first{kT0 + 5000, 40, 900};
    QList<JointRecord> joints = feed(d, first, kT0, first.returns(5) + 1000);
    QCOMPARE(joints.size(), 1);
    qint64 t = first.returns(5) + 1000;
    QVERIFY(!d.add(reading(t, kSetpoint + 8, 0))); // the overshoot
    const Curve second{t + 500, 40, 900};
    joints += feed(d, second, t + kPollMs, kT0 + 15'000);
    QCOMPARE(joints.size(), 2);
    QVERIFY(std::abs(joints.at(1).startMs - second.leaves(5)) <= kPollMs / 2);
}

// A tool put in its stand goes to sleep: the tip leaves the band while the heater is off, and the
// status says so only later. That is an event of the port, never a joint.
void TestJointDetector::aTipThatFallsWhileTheHeaterIdlesIsNoJoint() {
    JointDetector d({}, 1);
    qint64 t = kT0;
    for (; t < kT0 + 3000; t += kPollMs)
        QVERIFY(!d.add(reading(t, kSetpoint, 10)));
    double tip = kSetpoint;
    for (int i = 0; i < 20; ++i, t += kPollMs) // cooling with the heater off, still "working"
        QVERIFY(!d.add(reading(t, tip -= 1.5, 0)));
    QVERIFY(d.inJoint()); // it looked like one until now
    QVERIFY(!d.add(reading(t, tip, 0, QStringLiteral("C245"), false))); // the status: asleep
    QVERIFY(!d.inJoint());
}

// A tip on its way back wobbles: one reading within the band, the next below it again. The joint
// goes on until the tip is back for good, and its recovery is that last return.
void TestJointDetector::aReadingBackInTheBandByWobbleDoesNotEndTheJoint() {
    JointDetector d({}, 1);
    qint64 t = kT0;
    for (; t < kT0 + 3000; t += kPollMs)
        QVERIFY(!d.add(reading(t, kSetpoint, 10)));
    const qint64 start = t;
    for (const int below : {30, 20, 12, 4, 7, 6, 2, 1, 0, 0, 1, 0, 0, 0, 0}) {
        const auto j = d.add(reading(t, kSetpoint - below, below > 2 ? 70 : 12));
        if (below > 1) {
            QVERIFY2(!j, qPrintable(QString::number(below)));
        } else if (j) {
            QVERIFY(j->recoveryMs);
            // Back at the edge between the readings 6 and 2 K below, not at the wobble's 4 K.
            QVERIFY2(*j->recoveryMs > 500 && *j->recoveryMs < 700,
                     qPrintable(QString::number(*j->recoveryMs)));
            QVERIFY(j->startMs < start);
            return;
        }
        t += kPollMs;
    }
    QFAIL("the joint never ended");
}

// An exponential return read every 150 ms in whole degrees: the readings sit on one value for
// several polls near the band's edge, yet the fit places the return within half the spacing of
// where the tip truly crossed the edge, and the recovery within that and the start's uncertainty.
void TestJointDetector::aSlowRecoveryIsPlacedFinerThanTheSpacingAndTheWholeDegrees() {
    for (const qint64 phase : {0, 37, 74, 111}) {
        JointDetector d({}, 1);
        const qint64 t0 = kT0 + 3000 + phase;
        const double tau = 900; // ms
        const auto below = [&](qint64 t) {
            const double d = double(t - t0);
            if (d <= 0)
                return 0.0;
            return d < 100 ? 45 * d / 100 : 45 * std::exp(-(d - 100) / tau);
        };
        // The true crossing of the edge, 5.5 K below, on the way down and up.
        const double leave = t0 + 100 * 5.5 / 45;
        const double back = t0 + 100 + tau * std::log(45 / 5.5);
        std::optional<JointRecord> j;
        for (qint64 t = kT0; t < kT0 + 8000 && !j; t += 150)
            j = d.add(reading(t, kSetpoint - below(t), below(t) > 1 ? 90 : 10));
        QVERIFY(j && j->recoveryMs);
        const double returnError = std::abs(double(j->startMs + *j->recoveryMs) - back);
        QVERIFY2(returnError < 75, qPrintable(QString::number(returnError)));
        QVERIFY(std::abs(double(j->startMs) - leave) <= double(j->startUncertaintyMs));
        const double error = std::abs(double(*j->recoveryMs) - (back - leave));
        QVERIFY2(error <= 75 + double(j->startUncertaintyMs),
                 qPrintable(QStringLiteral("phase %1: %2 ms vs %3 ms")
                                .arg(phase)
                                .arg(*j->recoveryMs)
                                .arg(back - leave)));
        QVERIFY(!j->recoveryBounded);
    }
}

// A deep joint (80 K) whose heater brings the tip back as a first-order return (τ 1.1 s), read
// every 60 to 110 ms in whole degrees on a tip that wobbles ±1.2 K in a 1.7 s swing with a fast
// ripple on it: near the band's edge the return climbs 5 K/s, so the swing alone moves the
// readings around the edge by a quarter of a second, and a fit through them there follows it.
// The whole climb, tens of kelvin against the same wobble, says where the return crosses.
void TestJointDetector::aDeepSlowReturnOnAWobblingTipIsPlacedByItsWholeClimb() {
    constexpr double kDip = 80, kTauMs = 1100, kFallMs = 200;
    const auto below = [&](double ms) {
        if (ms <= 0)
            return 0.0;
        return ms < kFallMs ? kDip * ms / kFallMs : kDip * std::exp(-(ms - kFallMs) / kTauMs);
    };
    const double leave = kFallMs * 5.5 / kDip;
    const double back = kFallMs + kTauMs * std::log(kDip / 5.5);
    RecoveryErrors errors;
    for (const double phase : kWobblePhases) {
        const auto j = wobblingJoint(below, phase, 90);
        QVERIFY(j && j->recoveryMs);
        errors.add(*j, back - leave);
    }
    QVERIFY2(errors.allHeld, qPrintable(errors.all));
    QVERIFY2(errors.worstMeasuredMs <= 100, qPrintable(errors.all));
}

// A heater at full power climbs straight: the few readings around the edge follow a slow wobble
// there by a hundred milliseconds and more, a line through the whole climb does not.
void TestJointDetector::aStraightReturnOnAWobblingTipIsPlacedByItsWholeClimb_data() {
    QTest::addColumn<double>("dip");
    QTest::addColumn<double>("climbMs");
    QTest::addColumn<double>("worstMs");
    // A climb shorter than the wobble's swing cannot average it: the bound there is what any fit
    // across it leaves. A slow, shallow climb is only bounded, and its bounds must hold.
    QTest::newRow("60 K over 2.8 s") << 60.0 << 2800.0 << 50.0;
    QTest::newRow("30 K over 1.6 s") << 30.0 << 1600.0 << 110.0;
    QTest::newRow("20 K over 4 s") << 20.0 << 4000.0 << 0.0;
}

void TestJointDetector::aStraightReturnOnAWobblingTipIsPlacedByItsWholeClimb() {
    QFETCH(double, dip);
    QFETCH(double, climbMs);
    QFETCH(double, worstMs);
    constexpr double kFallMs = 150;
    const auto below = [&](double ms) {
        if (ms <= 0 || ms >= kFallMs + climbMs)
            return 0.0;
        return ms < kFallMs ? dip * ms / kFallMs : dip * (1 - (ms - kFallMs) / climbMs);
    };
    const double leave = kFallMs * 5.5 / dip;
    const double back = kFallMs + climbMs * (1 - 5.5 / dip);
    RecoveryErrors errors;
    for (const double phase : kWobblePhases) {
        const auto j = wobblingJoint(below, phase, 100);
        QVERIFY(j && j->recoveryMs);
        errors.add(*j, back - leave);
    }
    QVERIFY2(errors.allHeld, qPrintable(errors.all));
    QVERIFY2(errors.worstMeasuredMs <= worstMs, qPrintable(errors.all));
}

// Readings of a simulated station whose tip wobbles ±2 K (a 2 s swing and a fast ripple): a
// straight 29 K climb that the wobble bends into what looks like a first-order return, whose curve
// crosses the edge 350 ms after the true return, beyond the first reading back in the band. The
// stated interval must still hold the truth.
void TestJointDetector::aReturnTheFitAndTheReadingsDisagreeOnReachesAcrossBoth() {
    const std::pair<qint64, int> readings[] = {
        {-3487, 349}, {-3335, 349}, {-3145, 350}, {-2996, 349}, {-2859, 349}, {-2712, 349},
        {-2590, 348}, {-2395, 350}, {-2232, 349}, {-2098, 351}, {-1959, 350}, {-1764, 350},
        {-1640, 351}, {-1454, 350}, {-1255, 351}, {-1070, 352}, {-949, 350},  {-762, 351},
        {-581, 350},  {-400, 348},  {-247, 349},  {-96, 348},   {89, 320},    {152, 321},
        {216, 323},   {273, 324},   {307, 325},   {353, 325},   {415, 326},   {481, 328},
        {523, 329},   {570, 329},   {640, 329},   {710, 331},   {757, 333},   {801, 333},
        {844, 334},   {901, 333},   {971, 335},   {1036, 336},  {1099, 337},  {1165, 337},
        {1217, 337},  {1247, 338},  {1299, 339},  {1364, 340},  {1400, 340},  {1464, 340},
        {1495, 341},  {1549, 342},  {1599, 343},  {1651, 343},  {1704, 343},  {1738, 343},
        {1787, 345},  {1915, 347},  {2101, 349},  {2291, 349},  {2487, 350},  {2673, 352},
        {2865, 352},  {3035, 350},  {3178, 351},  {3333, 349}};
    constexpr qint64 kTrueRecoveryMs = 1680;
    JointDetector d({}, 1);
    std::optional<JointRecord> j;
    for (const auto &[ms, tip] : readings)
        if (const auto ended = d.add(reading(kT0 + ms, tip, tip < 345 ? 90 : 8)))
            j = ended;
    if (!j)
        j = afterReturn(d, kT0 + readings[std::size(readings) - 1].first, 150);
    QVERIFY(j && j->recoveryMs);
    const qint64 error = j->startMs + *j->recoveryMs - (kT0 + kTrueRecoveryMs);
    QVERIFY2(
        std::abs(error) <= j->recoveryUncertaintyMs,
        qPrintable(
            QStringLiteral("%1 ms off, said ±%2 ms").arg(error).arg(j->recoveryUncertaintyMs)));
}

void TestJointDetector::theDipIsGivenWithAnIntervalThatHoldsIt_data() {
    QTest::addColumn<double>("dip");
    QTest::addColumn<double>("fallMs");
    QTest::addColumn<double>("wobbleK");
    // What the interval may be at most, to be of use: the span between the lowest reading and
    // the deepest the readings allow (up to 12 K here), the whole degree and the wobble's reach.
    QTest::addColumn<double>("widestK");
    QTest::newRow("a deep, sharp bottom, a quiet tip") << 80.0 << 120.0 << 0.0 << 13.0;
    QTest::newRow("a deep, sharp bottom, a wobbling tip") << 60.0 << 150.0 << 2.0 << 15.0;
    QTest::newRow("a shallow, round bottom, a wobbling tip") << 15.0 << 350.0 << 1.0 << 6.0;
}

// The lowest point of a quarter-sine fall into a first-order return (the simulator's shapes, and
// a heater's), read every 70 to 150 ms in whole degrees, at eight phases of the readings and the
// wobble: the dip given must lie within its stated uncertainty of the truth every time, and the
// interval stay narrow enough to judge by. A wobbling tip's lowest reading is the one the wobble
// carried lowest, and a sharp bottom read 150 ms apart is passed between readings by several
// kelvin: such bottoms are given up to 7.5 K too shallow, and were said to be within ±0.5 K.
void TestJointDetector::theDipIsGivenWithAnIntervalThatHoldsIt() {
    QFETCH(double, dip);
    QFETCH(double, fallMs);
    QFETCH(double, wobbleK);
    QFETCH(double, widestK);
    constexpr double kTauMs = 900;
    const qint64 spacings[] = {150, 95, 70, 130, 110, 80, 140, 75};
    QString all;
    for (int phase = 0; phase < 8; ++phase) {
        JointDetector d({}, 1);
        const qint64 t0 = kT0 + 4000 + phase * 17;
        const auto below = [&](qint64 t) {
            const double ms = double(t - t0);
            if (ms <= 0)
                return 0.0;
            return ms < fallMs ? dip * std::sin(M_PI / 2 * ms / fallMs)
                               : dip * std::exp(-(ms - fallMs) / kTauMs);
        };
        std::optional<JointRecord> j;
        size_t k = phase;
        for (qint64 t = kT0; t < kT0 + 12'000 && !j; t += spacings[k++ % std::size(spacings)]) {
            const double s = double(t - kT0) / 1000;
            const double wobble = wobbleK * (0.6 * std::sin(s * 3.1 + phase) +
                                             0.4 * std::sin(s * 23.7 + 2.0 * phase));
            j = d.add(reading(t, kSetpoint - below(t) + wobble, below(t) > 1 ? 90 : 10));
        }
        QVERIFY(j);
        const double error = j->dipDepth - dip;
        all += QStringLiteral(" %1±%2").arg(error, 0, 'f', 1).arg(j->dipUncertaintyK, 0, 'f', 1);
        QVERIFY2(std::abs(error) <= j->dipUncertaintyK, qPrintable(all));
        QVERIFY2(j->dipUncertaintyK <= widestK, qPrintable(all));
    }
}

void TestJointDetector::
    aRecoveryBetweenReadingsFarApartIsBoundedAndJudgedOnlyWhereTheBoundsAllow_data() {
    QTest::addColumn<qint64>("limitMs");
    QTest::addColumn<JointVerdict>("verdict");
    QTest::newRow("the limit inside the bounds") << qint64(1500) << JointVerdict::Incomplete;
    QTest::newRow("the limit above them") << qint64(5000) << JointVerdict::Ok;
    QTest::newRow("the limit below them") << qint64(500) << JointVerdict::SlowRecovery;
}

// Readings a second apart around the return: the recovery lies between them, no finer.
void TestJointDetector::
    aRecoveryBetweenReadingsFarApartIsBoundedAndJudgedOnlyWhereTheBoundsAllow() {
    QFETCH(qint64, limitMs);
    QFETCH(JointVerdict, verdict);
    JointDetector d({}, 1, JointLimits{5, limitMs, 80});
    qint64 t = kT0;
    for (; t < kT0 + 3000; t += 1000)
        QVERIFY(!d.add(reading(t, kSetpoint, 10)));
    QVERIFY(!d.add(reading(t, kSetpoint - 30, 90)));
    QVERIFY(!d.add(reading(t += 1000, kSetpoint - 20, 90)));
    QVERIFY(!d.add(reading(t += 1000, kSetpoint, 10)));
    QVERIFY(!d.add(reading(t += 1000, kSetpoint, 10)));
    const auto j = afterReturn(d, t, 1000);
    QVERIFY(j && j->recoveryMs);
    QVERIFY(j->recoveryBounded);
    QVERIFY(j->recoveryUncertaintyMs >= 500);
    QCOMPARE(j->verdict, verdict);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJointDetector)

} // namespace tst_jointdetector
#include "tst_jointdetector.moc"
