// The joints a shape set draws are the ones it promises (depth, drop, recovery, form, overshoot),
// the same seed draws the same ones, and every shape, exponential or straight, with or without an
// overshoot, is back at the band's edge exactly its recovery after leaving it: the truth the
// benchmark measures clients by. A station on a noisy set wobbles through its joints, and what
// its tip was when read is kept with the joint.
#include "sim/jointshapeset.h"
#include "sim/simline.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_jointshapeset {

using namespace tipscope::sim;
using tipscope::protocol::Frame;

class TestJointShapeSet : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void eachSetDrawsWhatItPromises_data();
    void eachSetDrawsWhatItPromises();
    void anUnknownSetIsNone();
    void everyShapeIsBackAtTheEdgeAfterItsRecovery_data();
    void everyShapeIsBackAtTheEdgeAfterItsRecovery();
    void aNoisyStationWobblesThroughItsJointsAndKeepsWhatWasRead();
};

void TestJointShapeSet::eachSetDrawsWhatItPromises_data() {
    QTest::addColumn<QString>("name");
    for (const QString &name : JointShapeSet::names())
        QTest::newRow(qPrintable(name)) << name;
}

void TestJointShapeSet::eachSetDrawsWhatItPromises() {
    QFETCH(QString, name);
    const auto set = JointShapeSet::named(name);
    QVERIFY(set);
    QCOMPARE(set->name, name);
    QRandomGenerator random(11), again(11);
    int linear = 0, overshooting = 0;
    for (int i = 0; i < 2000; ++i) {
        const JointSpec spec = set->draw(random);
        const JointSpec same = set->draw(again);
        QCOMPARE(same.depthK, spec.depthK);
        QCOMPARE(same.recoveryMs, spec.recoveryMs);
        QCOMPARE(same.dropMs, spec.dropMs);
        QVERIFY(spec.depthK >= set->minDepthK && spec.depthK <= set->maxDepthK);
        QVERIFY(spec.recoveryMs >= set->minRecoveryMs && spec.recoveryMs <= set->maxRecoveryMs);
        if (set->maxDropMs > 0)
            QVERIFY2(spec.dropMs >= set->minDropMs && spec.dropMs <= set->maxDropMs,
                     qPrintable(QString::number(spec.dropMs)));
        else
            QCOMPARE(spec.dropMs, 0.0); // a quarter of the recovery, as JointShape makes it
        QVERIFY(spec.overshootK >= 0 && spec.overshootK <= set->maxOvershootK);
        linear += spec.form == RecoveryForm::Linear;
        overshooting += spec.overshootK > 0.5;
    }
    // The shares come out as the set says, give or take what 2000 draws allow.
    QVERIFY2(qAbs(linear / 2000.0 - set->linearShare) < 0.05, qPrintable(QString::number(linear)));
    QCOMPARE(overshooting > 0, set->maxOvershootK > 0.5);
}

void TestJointShapeSet::anUnknownSetIsNone() {
    QVERIFY(!JointShapeSet::named(QStringLiteral("fast")));
    QVERIFY(!JointShapeSet::named(QString()));
}

void TestJointShapeSet::everyShapeIsBackAtTheEdgeAfterItsRecovery_data() {
    QTest::addColumn<int>("depth");
    QTest::addColumn<int>("recovery");
    QTest::addColumn<double>("drop");
    QTest::addColumn<bool>("linear");
    QTest::addColumn<double>("overshoot");
    QTest::newRow("the demo's") << 50 << 1500 << 0.0 << false << 0.0;
    QTest::newRow("shallow, slow, straight") << 10 << 6000 << 400.0 << true << 0.0;
    QTest::newRow("deep, fast drop, straight, overshoot") << 90 << 600 << 50.0 << true << 3.0;
    QTest::newRow("deep, exponential, overshoot") << 120 << 3500 << 150.0 << false << 2.0;
    QTest::newRow("drop longer than the recovery allows") << 30 << 100 << 400.0 << true << 0.0;
}

void TestJointShapeSet::everyShapeIsBackAtTheEdgeAfterItsRecovery() {
    QFETCH(int, depth);
    QFETCH(int, recovery);
    QFETCH(double, drop);
    QFETCH(bool, linear);
    QFETCH(double, overshoot);
    const JointShape shape(JointSpec{depth, recovery, drop,
                                     linear ? RecoveryForm::Linear : RecoveryForm::Exponential,
                                     overshoot});
    // A recovery shorter than the drop needs is lengthened; the shape says the one it made.
    QVERIFY(shape.recoveryMs() >= recovery);
    const double leave = shape.leaveMs();
    const double back = leave + double(shape.recoveryMs());
    QCOMPARE(qRound(shape.belowTargetK(leave) * 100), qRound(JointShape::kEdgeK * 100));
    QCOMPARE(qRound(shape.belowTargetK(back) * 100), qRound(JointShape::kEdgeK * 100));
    QVERIFY(shape.belowTargetK(back - 5) > JointShape::kEdgeK);
    QVERIFY(shape.belowTargetK(back + 5) < JointShape::kEdgeK);
    QCOMPARE(qRound(shape.belowTargetK(shape.dropMs())), depth); // the lowest point
    double lowest = 0, highest = 0;
    for (double t = 0; t < shape.durationMs(); t += 1) {
        lowest = qMax(lowest, shape.belowTargetK(t));
        highest = qMin(highest, shape.belowTargetK(t));
    }
    QCOMPARE(qRound(lowest * 10), depth * 10);
    QVERIFY2(qAbs(-highest - overshoot) < 0.6, qPrintable(QString::number(highest)));
    QCOMPARE(shape.belowTargetK(shape.durationMs()), 0.0);
    // The record of the shape makes the same shape again (what the benchmark rebuilds).
    const SimJoint made = shape.made(2, 1000);
    QCOMPARE(made.startMs, 1000 + qRound64(leave));
    const JointShape again(made);
    QCOMPARE(again.recoveryMs(), shape.recoveryMs());
    QCOMPARE(again.durationMs(), shape.durationMs());
}

void TestJointShapeSet::aNoisyStationWobblesThroughItsJointsAndKeepsWhatWasRead() {
    SimLine line;
    auto *station = static_cast<SimStation *>(
        line.addDevice(std::make_unique<SimStation>(QStringLiteral("DME"))));
    QSignalSpy begun(&line, &SimLine::jointMade);
    QSignalSpy ended(&line, &SimLine::jointEnded);
    QVERIFY(begun.isValid() && ended.isValid());
    line.advance(10'000); // heated up
    station->setReadingNoise(2, true);
    const auto made = station->startJoint(1, JointSpec{40, 1500, 150, RecoveryForm::Linear, 2});
    QVERIFY(made);
    QCOMPARE(made->form, RecoveryForm::Linear);
    // Read the tip every 100 ms as a client would, through the protocol.
    QSet<int> offsets; // reading minus the rounded true tip
    int reads = 0;
    while (ended.isEmpty() && reads < 200) {
        line.advance(100);
        const Frame answer = station->handle(Frame::read("TT1").addressed(0, 1));
        ++reads;
        if (station->port(1).joint)
            offsets.insert(answer.data.toInt() - qRound(station->port(1).tip));
    }
    QCOMPARE(begun.size(), 1);
    QCOMPARE(ended.size(), 1);
    const SimJoint over = ended.first().first().value<SimJoint>();
    QCOMPARE(over.startMs, begun.first().first().value<SimJoint>().startMs);
    QCOMPARE(over.port, 1);
    QVERIFY2(over.reads >= 15, qPrintable(QString::number(over.reads)));
    // Read every 100 ms, the deepest instant read lies within the first 100 ms of the bottom.
    QVERIFY2(over.readDepthK > 35 && over.readDepthK <= 40,
             qPrintable(QString::number(over.readDepthK)));
    QVERIFY2(offsets.size() >= 3, "the readings should wobble during the joint");
    for (const int offset : std::as_const(offsets))
        QVERIFY(qAbs(offset) <= 2);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJointShapeSet)

} // namespace tst_jointshapeset
#include "tst_jointshapeset.moc"
