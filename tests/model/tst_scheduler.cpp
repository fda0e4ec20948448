// The poll scheduler spends the wire where people look and never floods the queue.
#include "simfixture.h"

#include "model/pollscheduler.h"

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::testing;

class TestScheduler : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void visiblePortsUpdateFasterThanHiddenOnes();
    void neverMoreThanMaxInFlightPollsAreQueued();
    void settingsAreReadOnceAndAgainOnRequest();
    void aClosedLinePausesPollingInsteadOfSpinning();
};

void TestScheduler::visiblePortsUpdateFasterThanHiddenOnes() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    f.simLine->setClockRunning(true);
    f.simLine->setBaud(19200);
    auto st = f.station();
    PollScheduler s;
    s.addDevice(st.get());
    s.setVisiblePorts(st.get(), {1});
    s.setInterval(PollClass::Live, 100);
    s.setInterval(PollClass::Status, 1000);
    s.start();
    QTest::qWait(4000);
    const double visible = st->parameter("TT1")->achievedRateHz();
    const double hidden = st->parameter("TT3")->achievedRateHz();
    QVERIFY2(visible > 2 * hidden && hidden > 0,
             qPrintable(QStringLiteral("visible %1 Hz, hidden %2 Hz").arg(visible).arg(hidden)));
}

void TestScheduler::neverMoreThanMaxInFlightPollsAreQueued() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    f.simLine->setBaud(19200);
    auto st = f.station();
    PollScheduler s;
    s.addDevice(st.get());
    s.setVisiblePorts(st.get(), {1, 2, 3, 4});
    s.setMaxInFlight(2);
    s.start();
    int worst = 0;
    QTimer probe;
    connect(&probe, &QTimer::timeout, this,
            [&] { worst = qMax(worst, f.line->queue().pendingCount()); });
    probe.start(1);
    QTest::qWait(1500);
    QVERIFY(s.pollsDone() > 10);
    QVERIFY2(worst <= 2, qPrintable(QString::number(worst)));
}

void TestScheduler::settingsAreReadOnceAndAgainOnRequest() {
    SimFixture f(singleDevice(QStringLiteral("DDR")));
    auto st = f.station();
    PollScheduler s;
    s.addDevice(st.get());
    s.setInterval(PollClass::Live, 0);
    s.setInterval(PollClass::Status, 0);
    s.setInterval(PollClass::Counter, 0);
    s.start();
    QTRY_VERIFY(st->parameter("PLM")->value().has_value());
    f.settle();
    const qint64 after = f.simLine->stats().requests;
    QTest::qWait(300);
    QCOMPARE(f.simLine->stats().requests, after); // nothing periodic left
    f.simLine->station()->setSetting("PLM", 700);
    s.requestRefresh(st.get(), PollClass::Settings);
    QTRY_COMPARE(st->parameter("PLM")->number().value_or(0), 700);
}

void TestScheduler::aClosedLinePausesPollingInsteadOfSpinning() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    f.line->close();
    PollScheduler s;
    s.addDevice(st.get());
    s.start();
    QTest::qWait(1500);
    // Each pause lasts a second: a couple of rounds of failures, not thousands.
    QVERIFY2(s.pollsDone() < 20, qPrintable(QString::number(s.pollsDone())));
}

QTEST_GUILESS_MAIN(TestScheduler)
#include "tst_scheduler.moc"
