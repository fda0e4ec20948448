// DemoActivity plays a station in use on the demo line: port 1's joints dip the tip and the
// controller brings it back, port 2 rests in the stand (and sleeps) and is picked up again, the
// feeder feeds its 2 s and stops; a port without a tool is left alone, and without the activity
// the demo line changes nothing by itself.
#include "sim/simline.h"
#include "testmain.h"

#include <QTest>

namespace tst_demoactivity {

using namespace tipscope::sim;

namespace {
constexpr int kStepMs = 100;

// Advances the line to `untilMs` of activity time in poll-sized steps, keeping the lowest tip of
// `port` on the way.
double runTo(SimLine &line, qint64 fromMs, qint64 untilMs, int port) {
    double lowest = 1e9;
    for (qint64 t = fromMs; t < untilMs; t += kStepMs) {
        line.advance(kStepMs);
        lowest = qMin(lowest, line.station()->port(port).tip);
    }
    return lowest;
}
} // namespace

class TestDemoActivity : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aJointDipsPort1AndTheTipRecovers();
    void port2RestsInTheStandAndIsPickedUpAgain();
    void theFeederFeedsTwoSecondsAndStops();
    void aPortWithoutAToolIsLeftAlone();
    void whatSomeoneElseStartedIsLeftToThem();
    void aStallLongerThanAFeedStartsNoFeed();
    void withoutTheActivityTheDemoChangesNothingByItself();
};

void TestDemoActivity::aJointDipsPort1AndTheTipRecovers() {
    auto line = SimLine::demo();
    line->setDemoActivity(true);
    runTo(*line, 0, DemoActivity::kJointOffsetMs, 1);
    const double settled = line->station()->port(1).tip;
    QVERIFY2(qAbs(settled - 350) < 3, qPrintable(QString::number(settled))); // heated up by then
    const double dip =
        runTo(*line, DemoActivity::kJointOffsetMs, DemoActivity::kJointOffsetMs + 1500, 1);
    QVERIFY2(dip < 330 && dip > 250, qPrintable(QString::number(dip)));
    runTo(*line, DemoActivity::kJointOffsetMs + 1500, DemoActivity::kJointOffsetMs + 5000, 1);
    const double recovered = line->station()->port(1).tip;
    QVERIFY2(qAbs(recovered - 350) < 5, qPrintable(QString::number(recovered)));
    // And again a period later.
    const qint64 next = DemoActivity::kJointOffsetMs + DemoActivity::kJointEveryMs;
    runTo(*line, DemoActivity::kJointOffsetMs + 5000, next, 1);
    QVERIFY(runTo(*line, next, next + 1500, 1) < 330);
}

void TestDemoActivity::port2RestsInTheStandAndIsPickedUpAgain() {
    auto line = SimLine::demo();
    line->setDemoActivity(true);
    runTo(*line, 0, DemoActivity::kRestStartMs - kStepMs, 2);
    QCOMPARE(line->station()->port(2).status, 0);
    runTo(*line, DemoActivity::kRestStartMs - kStepMs, DemoActivity::kRestCycleMs - kStepMs, 2);
    const SimPort &resting = line->station()->port(2);
    QVERIFY2(resting.status == 1 || resting.status == 2,
             qPrintable(QString::number(resting.status)));
    QVERIFY2(resting.tip < 300, qPrintable(QString::number(resting.tip))); // cooled while resting
    runTo(*line, DemoActivity::kRestCycleMs - kStepMs, DemoActivity::kRestCycleMs + 8000, 2);
    QCOMPARE(line->station()->port(2).status, 0);
    QVERIFY2(qAbs(line->station()->port(2).tip - 350) < 5,
             qPrintable(QString::number(line->station()->port(2).tip)));
}

void TestDemoActivity::theFeederFeedsTwoSecondsAndStops() {
    auto line = SimLine::demo();
    line->setDemoActivity(true);
    const SimFeeder *feeder = line->feeder();
    runTo(*line, 0, DemoActivity::kFeedOffsetMs - kStepMs, 1);
    QVERIFY(!feeder->isFeeding());
    QCOMPARE(feeder->fedDmm(), 0.0);
    runTo(*line, DemoActivity::kFeedOffsetMs - kStepMs, DemoActivity::kFeedOffsetMs + 1000, 1);
    QVERIFY(feeder->isFeeding());
    runTo(*line, DemoActivity::kFeedOffsetMs + 1000,
          DemoActivity::kFeedOffsetMs + DemoActivity::kFeedMs + 1000, 1);
    QVERIFY(!feeder->isFeeding());
    QVERIFY2(feeder->fedDmm() > 100, qPrintable(QString::number(feeder->fedDmm())));
    // A feeder in error does not feed.
    line->feeder()->setError(3);
    runTo(*line, DemoActivity::kFeedOffsetMs + DemoActivity::kFeedMs + 1000,
          DemoActivity::kFeedOffsetMs + DemoActivity::kFeedEveryMs + 1000, 1);
    QVERIFY(!feeder->isFeeding());
}

void TestDemoActivity::aPortWithoutAToolIsLeftAlone() {
    auto line = SimLine::demo();
    line->station()->setTool(1, 0);
    line->setDemoActivity(true);
    const double lowest = runTo(*line, 0, DemoActivity::kJointOffsetMs + 3000, 1);
    QCOMPARE(lowest, SimStation::kAmbient);
    QVERIFY(!line->station()->port(1).joint);
}

void TestDemoActivity::whatSomeoneElseStartedIsLeftToThem() {
    auto line = SimLine::demo();
    line->setDemoActivity(true);
    // A feed started on the line (W-SFD) before the activity's own: it keeps feeding past the
    // activity's stop time, and the activity starts none of its own over it.
    line->feeder()->startFeed();
    runTo(*line, 0, DemoActivity::kFeedOffsetMs + DemoActivity::kFeedMs + 1000, 1);
    QVERIFY(line->feeder()->isFeeding());
    // Port 2 put in the stand by someone else stays there when the activity's rest would end.
    line->station()->setStatus(2, 1);
    runTo(*line, DemoActivity::kFeedOffsetMs + DemoActivity::kFeedMs + 1000,
          DemoActivity::kRestCycleMs + 1000, 2);
    QVERIFY(line->station()->port(2).status != 0);
}

void TestDemoActivity::aStallLongerThanAFeedStartsNoFeed() {
    auto line = SimLine::demo();
    line->setDemoActivity(true);
    runTo(*line, 0, DemoActivity::kFeedOffsetMs - kStepMs, 1);
    line->advance(DemoActivity::kFeedMs + 2 * kStepMs); // start and stop in one step
    QVERIFY(!line->feeder()->isFeeding());
}

void TestDemoActivity::withoutTheActivityTheDemoChangesNothingByItself() {
    auto line = SimLine::demo();
    QVERIFY(!line->hasDemoActivity());
    runTo(*line, 0, DemoActivity::kRestCycleMs + 1000, 2);
    QVERIFY(runTo(*line, 0, DemoActivity::kJointEveryMs, 1) > 345);
    QCOMPARE(line->station()->port(2).status, 0);
    QVERIFY(!line->feeder()->isFeeding());
    QCOMPARE(line->feeder()->fedDmm(), 0.0);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestDemoActivity)

} // namespace tst_demoactivity
#include "tst_demoactivity.moc"
