// RandomJoints on one simulated station, without a line: every port at work gets joints, none
// before its tip has rested the set's rest after the last one, none while it is in the stand; the
// rate asked is a ceiling, and a seed makes the same joints again, another seed others.
#include "sim/jointshapeset.h"
#include "sim/randomjoints.h"
#include "sim/simstation.h"
#include "testmain.h"

#include <QTest>

namespace tst_randomjoints {

using namespace tipscope::sim;

namespace {

constexpr int kStepMs = 20;
constexpr int kHeatUpMs = 10'000;
constexpr int kRunMs = 180'000;

// The joints started on a DME's ports over kRunMs, after a heat-up; `standing` rests in the stand.
QList<SimJoint> run(double perMinute, quint32 seed, int standing = 0) {
    SimStation station(QStringLiteral("DME"));
    if (standing > 0)
        station.setStatus(standing, 1);
    for (int t = 0; t < kHeatUpMs; t += kStepMs)
        station.advance(kStepMs);
    RandomJoints joints(&station, perMinute, seed);
    QList<SimJoint> made;
    for (int t = 0; t < kRunMs; t += kStepMs) {
        station.advance(kStepMs);
        joints.advance(kStepMs);
        made += station.takeMadeJoints();
    }
    return made;
}

QString describe(const QList<SimJoint> &joints) {
    QStringList out;
    for (const SimJoint &j : joints)
        out << QStringLiteral("P%1@%2:%3K").arg(j.port).arg(j.startMs).arg(j.depthK);
    return out.join(QLatin1Char(' '));
}

} // namespace

class TestRandomJoints : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyPortAtWorkGetsJointsAfterItsTipRested();
    void theRateAskedIsACeiling();
    void aPortInTheStandGetsNone();
    void aSeedMakesTheSameJointsAgain();
};

void TestRandomJoints::everyPortAtWorkGetsJointsAfterItsTipRested() {
    const QList<SimJoint> made = run(6, 7);
    const int rest = JointShapeSet::named(QStringLiteral("demo"))->restMs;
    QMap<int, QList<SimJoint>> byPort;
    for (const SimJoint &j : made)
        byPort[j.port].append(j);
    QCOMPARE(byPort.keys(), (QList<int>{1, 2, 3, 4}));
    for (const QList<SimJoint> &joints : std::as_const(byPort)) {
        QVERIFY2(joints.size() >= 5, qPrintable(describe(joints)));
        // Not one before the last is over and the tip rested: its drop, its recovery, the rest.
        for (qsizetype i = 1; i < joints.size(); ++i) {
            const SimJoint &last = joints.at(i - 1);
            QVERIFY2(joints.at(i).startMs >= last.startMs + last.recoveryMs + rest,
                     qPrintable(describe(joints)));
        }
    }
}

// Ten a minute asked on each port: a joint lasts seconds and the tip must rest after it, so the
// ports make what they can, never more than asked.
void TestRandomJoints::theRateAskedIsACeiling() {
    const QList<SimJoint> made = run(10, 7);
    const double minutes = double(kRunMs) / 60'000;
    QMap<int, int> perPort;
    for (const SimJoint &j : made)
        ++perPort[j.port];
    for (auto it = perPort.cbegin(); it != perPort.cend(); ++it)
        QVERIFY2(it.value() <= 10 * minutes * 1.5 && it.value() >= 3 * minutes,
                 qPrintable(QStringLiteral("port %1: %2 joints").arg(it.key()).arg(it.value())));
}

void TestRandomJoints::aPortInTheStandGetsNone() {
    const QList<SimJoint> made = run(6, 7, 2);
    QSet<int> ports;
    for (const SimJoint &j : made)
        ports.insert(j.port);
    QCOMPARE(ports, (QSet<int>{1, 3, 4}));
}

void TestRandomJoints::aSeedMakesTheSameJointsAgain() {
    const QList<SimJoint> first = run(6, 7);
    const QList<SimJoint> again = run(6, 7);
    QCOMPARE(describe(again), describe(first));
    QVERIFY(describe(run(6, 8)) != describe(first));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestRandomJoints)

} // namespace tst_randomjoints

#include "tst_randomjoints.moc"
