// The poll scheduler spends the wire where people look and never floods the queue.
#include "model/simfixture.h"
#include "testmain.h"

#include "model/device/portmodel.h"
#include "model/live/pollscheduler.h"

#include <algorithm>
#include <cstdlib>

namespace tst_pollscheduler {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::testing;

namespace {
// A DME on a running line paced at 19200 baud, its model polled by `s` with `visible` on screen
// and live values due every 100 ms, which the wire cannot carry for four ports.
std::unique_ptr<StationModel> pacedStation(SimFixture &f, PollScheduler &s,
                                           const QSet<int> &visible) {
    f.simLine->setClockRunning(true);
    f.simLine->setBaud(19200);
    auto st = f.station();
    s.addDevice(st.get());
    s.setVisiblePorts(st.get(), visible);
    s.setInterval(PollClass::Live, 100);
    return st;
}
} // namespace

class TestScheduler : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void visiblePortsUpdateFasterThanHiddenOnesButEveryTipAlike();
    void neverMoreThanMaxInFlightPollsAreQueued();
    void settingsAreReadOnceAndAgainOnRequest();
    void aClosedLinePausesPollingInsteadOfSpinning();
    void aPortInAJointHasItsPowerPolledMoreOftenAndEveryTipAlike_data();
    void aPortInAJointHasItsPowerPolledMoreOftenAndEveryTipAlike();
    void aPortLeavingItsBandHasItsStatusReadAtOnce();
    void theWireASpareDuringAJointGoesToEveryTipAlike();
    void aWakeHasItsStatusReadAsTheTipClimbs();
    void fillingTheWireKeepsItBusyWithLiveValuesOnly_data();
    void fillingTheWireKeepsItBusyWithLiveValuesOnly();
};

// A port on screen has its live values read more often than one nobody looks at, but for the
// tip temperature and power, from which every port's joints are measured whatever is shown.
void TestScheduler::visiblePortsUpdateFasterThanHiddenOnesButEveryTipAlike() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    PollScheduler s;
    auto st = pacedStation(f, s, {1});
    s.setInterval(PollClass::Status, 1000);
    s.start();
    QTest::qWait(4000);
    const double visible = st->parameter("PS1")->achievedRateHz();
    const double hidden = st->parameter("PS3")->achievedRateHz();
    QVERIFY2(visible > 2 * hidden,
             qPrintable(QStringLiteral("visible %1 Hz, hidden %2 Hz").arg(visible).arg(hidden)));
    const double visibleTip = st->parameter("TT1")->achievedRateHz();
    const double hiddenTip = st->parameter("TT3")->achievedRateHz();
    QVERIFY2(
        hiddenTip > 0.5 * visibleTip && visibleTip > 0.5 * hiddenTip,
        qPrintable(QStringLiteral("visible %1 Hz, hidden %2 Hz").arg(visibleTip).arg(hiddenTip)));
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

void TestScheduler::aPortInAJointHasItsPowerPolledMoreOftenAndEveryTipAlike_data() {
    QTest::addColumn<bool>("adaptive");
    QTest::newRow("adaptive") << true;
    QTest::newRow("not adaptive") << false;
}

// Port 2 makes a long joint while port 4 rests, all four ports on screen, on a paced wire that
// cannot carry every live value at the live interval: adaptive, the busy port's power is read
// several times as often as the resting port's, and the two tips alike (the resting one times the
// next joint's start); not adaptive, both about as often.
void TestScheduler::aPortInAJointHasItsPowerPolledMoreOftenAndEveryTipAlike() {
    QFETCH(bool, adaptive);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    PollScheduler s;
    auto st = pacedStation(f, s, {1, 2, 3, 4});
    s.setAdaptive(adaptive);
    QCOMPARE(s.isAdaptive(), adaptive);
    s.start();
    // The ports heat up from cold first (busy: far below the setpoint, full power).
    QTRY_VERIFY_WITH_TIMEOUT(
        f.simLine->station()->canMakeJoint(2) && f.simLine->station()->canMakeJoint(4), 15000);
    QTRY_VERIFY_WITH_TIMEOUT(!s.isBusy(st.get(), 2) && !s.isBusy(st.get(), 4), 5000);
    QVERIFY(f.simLine->startJoint(2, 80, 8000));
    QTRY_VERIFY_WITH_TIMEOUT(s.isBusy(st.get(), 2), 2000);
    QVERIFY(!s.isBusy(st.get(), 4));
    QSignalSpy busyTip(st->parameter("TT2"), &Parameter::updated);
    QSignalSpy busyPower(st->parameter("PP2"), &Parameter::updated);
    QSignalSpy restingTip(st->parameter("TT4"), &Parameter::updated);
    QSignalSpy restingPower(st->parameter("PP4"), &Parameter::updated);
    QVERIFY(busyTip.isValid() && busyPower.isValid() && restingTip.isValid() &&
            restingPower.isValid());
    QTest::qWait(3000); // well inside the joint's recovery
    QVERIFY(s.isBusy(st.get(), 2));
    const QString counts = QStringLiteral("tip %1 vs %2, power %3 vs %4")
                               .arg(busyTip.size())
                               .arg(restingTip.size())
                               .arg(busyPower.size())
                               .arg(restingPower.size());
    QVERIFY2(restingTip.size() > 0 && restingPower.size() > 0, qPrintable(counts));
    QVERIFY2(2 * busyTip.size() < 3 * restingTip.size(), qPrintable(counts));
    QVERIFY2(2 * restingTip.size() < 3 * busyTip.size(), qPrintable(counts));
    if (adaptive)
        QVERIFY2(busyPower.size() > 2 * restingPower.size(), qPrintable(counts));
    else
        QVERIFY2(2 * busyPower.size() < 3 * restingPower.size(), qPrintable(counts));
}

// A port's status is due only every 8 s here (live values every 2 s, the status four times
// less often); when the port's tip leaves its band, its status is among the next few polls, so
// a tool put in its stand or asleep is seen as such when the tip shows it (counted in polls, not
// in time: about 60 polls go by in the half second the wire would otherwise take).
void TestScheduler::aPortLeavingItsBandHasItsStatusReadAtOnce() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    PollScheduler s;
    auto st = pacedStation(f, s, {1, 2, 3, 4});
    s.setInterval(PollClass::Live, 2000);
    s.start();
    QTRY_VERIFY_WITH_TIMEOUT(f.simLine->station()->canMakeJoint(2), 15000);
    QTRY_VERIFY_WITH_TIMEOUT(!s.isBusy(st.get(), 2), 5000);
    QSignalSpy status(st->parameter("PS2"), &Parameter::updated);
    QVERIFY(status.isValid());
    QVERIFY(status.wait(12000)); // just read: the next is due 8 s from now
    // The polls done when a reading (the tip's or the power's) made the port busy, and when its
    // status came next.
    std::optional<qint64> turnedBusyAt, statusAt;
    const auto noteBusy = [&] {
        if (!turnedBusyAt && s.isBusy(st.get(), 2))
            turnedBusyAt = s.pollsDone();
    };
    connect(st->parameter("TT2"), &Parameter::updated, this, noteBusy);
    connect(st->parameter("PP2"), &Parameter::updated, this, noteBusy);
    connect(st->parameter("PS2"), &Parameter::updated, this, [&] {
        if (turnedBusyAt && !statusAt)
            statusAt = s.pollsDone();
    });
    QVERIFY(f.simLine->startJoint(2, 60, 3000));
    QTRY_VERIFY_WITH_TIMEOUT(statusAt.has_value(), 5000);
    const qint64 after = *statusAt - *turnedBusyAt;
    QVERIFY2(after <= 6, qPrintable(QString::number(after)));
}

// Port 2 makes a long joint while the other three rest, at the live and status intervals a
// session uses, on a paced wire. What the wire has to spare goes first to port 2's tip while it
// falls, then to the tips, every port's alike: the busy one is measured from its readings, the
// next joint's start on any other port is timed from theirs. The busy port's power and the values
// that can wait (transistor temperature, time to sleep) keep to slower rates.
void TestScheduler::theWireASpareDuringAJointGoesToEveryTipAlike() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    PollScheduler s;
    auto st = pacedStation(f, s, {1, 2, 3, 4});
    s.setInterval(PollClass::Live, 250);
    s.setInterval(PollClass::Status, 2000);
    s.start();
    // Settings are read once at the start, on the turns of the rest: those reads done first.
    const auto allRead = [&st] {
        const QList<Parameter *> &all = st->parameters();
        return std::all_of(all.begin(), all.end(), [](const Parameter *p) {
            return !p->isReadable() || pollClassOf(p->meta()) == PollClass::None ||
                   p->value().has_value() || p->isRefused();
        });
    };
    QTRY_VERIFY_WITH_TIMEOUT(allRead(), 30000);
    QTRY_VERIFY_WITH_TIMEOUT(f.simLine->station()->canMakeJoint(2), 15000);
    QTRY_VERIFY_WITH_TIMEOUT(!s.isBusy(st.get(), 1) && !s.isBusy(st.get(), 2) &&
                                 !s.isBusy(st.get(), 3) && !s.isBusy(st.get(), 4),
                             5000);
    int all = 0;
    QMap<QString, int> reads;
    for (Parameter *p : st->parameters())
        connect(p, &Parameter::updated, this, [&all, &reads, p] {
            ++all;
            ++reads[QString::fromLatin1(p->code())];
        });
    // An event loop of its own: QTest::qWait() sleeps between its rounds of events and would
    // leave the wire idle.
    const auto runFor = [](int ms) {
        QEventLoop window;
        QTimer::singleShot(ms, &window, &QEventLoop::quit);
        window.exec();
    };
    QVERIFY(f.simLine->startJoint(2, 80, 8000));
    QTRY_VERIFY_WITH_TIMEOUT(s.isBusy(st.get(), 2), 2000);
    // Just turned busy: the fall and the lowest point, read first.
    all = 0;
    reads.clear();
    runFor(PollScheduler::kFallWatchMs - 100);
    const QString fall = QStringLiteral("TT1 %1, TT2 %2, TT3 %3, TT4 %4")
                             .arg(reads.value("TT1"))
                             .arg(reads.value("TT2"))
                             .arg(reads.value("TT3"))
                             .arg(reads.value("TT4"));
    qInfo().noquote() << "the fall:" << fall;
    for (const char *other : {"TT1", "TT3", "TT4"})
        QVERIFY2(2 * reads.value("TT2") >= 3 * reads.value(QLatin1String(other)), qPrintable(fall));
    runFor(200);
    // Then well inside the joint's recovery.
    all = 0;
    reads.clear();
    runFor(3000);
    QVERIFY(s.isBusy(st.get(), 2));
    QStringList counts;
    for (auto it = reads.begin(); it != reads.end(); ++it)
        counts << QStringLiteral("%1 %2").arg(it.key()).arg(it.value());
    const QString seen = QStringLiteral("of %1 reads: %2").arg(all).arg(counts.join(", "));
    qInfo().noquote() << seen;
    QVERIFY2(all > 0, qPrintable(seen));
    const int tips =
        reads.value("TT1") + reads.value("TT2") + reads.value("TT3") + reads.value("TT4");
    QVERIFY2(tips > 0.6 * all, qPrintable(seen));
    for (const char *tip : {"TT1", "TT2", "TT3", "TT4"}) {
        // Faster than their own 125 ms (24 reads in 3 s), each within a fifth of the others' mean.
        QVERIFY2(reads.value(QLatin1String(tip)) > 30, qPrintable(seen));
        QVERIFY2(std::abs(reads.value(QLatin1String(tip)) - tips / 4) < tips / 20,
                 qPrintable(seen));
    }
    // Its power no more often than the live interval says (a margin for the read at the turn).
    QVERIFY2(reads.value("PP2") <= 3 * 4 + 2, qPrintable(seen));
    QVERIFY2(reads.value("QT2") <= 1 && reads.value("ED2") <= 1, qPrintable(seen));
}

// Port 2 sleeps at 150 °C, its status due only every 8 s (live values every 2 s, as in the test
// above); while it sleeps it is no joint, so its tip is read at a resting port's rate. When the
// tool is picked up the tip climbs toward 350 °C, and the status that says "working" is read
// within a few polls of the climb being seen, not on its slow interval: a wake and its heat-up
// are timed from the curve.
void TestScheduler::aWakeHasItsStatusReadAsTheTipClimbs() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    f.simLine->station()->setStatus(2, 2);
    PollScheduler s;
    auto st = pacedStation(f, s, {1, 2, 3, 4});
    s.setInterval(PollClass::Live, 2000);
    s.start();
    const auto tip = [&st] { return st->parameter("TT2")->number().value_or(0); };
    const auto mode = [&st] {
        return PortStatus::fromNumber(st->parameter("PS2")->number().value_or(0)).mode;
    };
    QTRY_COMPARE_WITH_TIMEOUT(mode(), PortStatus::Mode::Sleep, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(tip() >= 147, 15000); // at its sleep temperature
    // Heating up to it under the sleep status was no wake either, once the status was read.
    QTRY_VERIFY_WITH_TIMEOUT(!s.isBusy(st.get(), 2), 10000);
    std::optional<qint64> climbSeenAt, workingAt;
    qint64 tipWhenWorking = 0;
    connect(st->parameter("TT2"), &Parameter::updated, this, [&] {
        if (!climbSeenAt && s.isBusy(st.get(), 2))
            climbSeenAt = s.pollsDone();
    });
    connect(st->parameter("PS2"), &Parameter::updated, this, [&] {
        if (climbSeenAt && !workingAt && mode() == PortStatus::Mode::Working) {
            workingAt = s.pollsDone();
            tipWhenWorking = tip();
        }
    });
    f.simLine->station()->setStatus(2, 0);
    QTRY_VERIFY_WITH_TIMEOUT(workingAt.has_value(), 8000);
    const QString seen = QStringLiteral("status %1 polls after the climb was seen, the tip at %2")
                             .arg(*workingAt - *climbSeenAt)
                             .arg(tipWhenWorking);
    qInfo().noquote() << seen;
    QVERIFY2(*workingAt - *climbSeenAt <= 6, qPrintable(seen));
    // Before the heat-up was over (the resting tip is read once a second here, so the climb is
    // seen up to a second after it began, and the simulated heater climbs fast).
    QVERIFY2(tipWhenWorking < 345, qPrintable(seen));
}

void TestScheduler::fillingTheWireKeepsItBusyWithLiveValuesOnly_data() {
    QTest::addColumn<bool>("fill");
    QTest::newRow("filling the wire") << true;
    QTest::newRow("by the intervals") << false;
}

// Live and status values due only every 4 s on a wire paced at 19200 baud. Filling the wire, the
// line spends most of its bytes' time reading live values early; settings, counters and identity,
// read once at the start, are not read again. By the intervals alone, the wire mostly idles.
void TestScheduler::fillingTheWireKeepsItBusyWithLiveValuesOnly() {
    QFETCH(bool, fill);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    PollScheduler s;
    auto st = pacedStation(f, s, {1, 2, 3, 4});
    s.setInterval(PollClass::Live, 4000);
    s.setInterval(PollClass::Status, 4000);
    s.setFillWire(fill);
    QCOMPARE(s.fillsWire(), fill);
    s.start();
    // Every setting, counter and identity value is read once at the start; then the window.
    std::vector<std::unique_ptr<QSignalSpy>> onceReads;
    for (Parameter *p : st->parameters()) {
        const PollClass c = p->isReadable() ? pollClassOf(p->meta()) : PollClass::None;
        if (c == PollClass::Settings || c == PollClass::Counter || c == PollClass::Identity)
            onceReads.push_back(std::make_unique<QSignalSpy>(p, &Parameter::updated));
    }
    QVERIFY(!onceReads.empty());
    const auto readOnce = [&onceReads] {
        return std::count_if(onceReads.begin(), onceReads.end(),
                             [](const auto &spy) { return spy->size() == 1; });
    };
    QTRY_COMPARE_WITH_TIMEOUT(readOnce(), std::ptrdiff_t(onceReads.size()), 30000);
    const sim::SimLineStats before = f.simLine->stats();
    QElapsedTimer window;
    window.start();
    QTest::qWait(2000);
    const sim::SimLineStats after = f.simLine->stats();
    const double wireBytes = double(window.elapsed()) / 1000 * 19200 / 10;
    const double busy =
        double(after.bytesSent + after.bytesReceived - before.bytesSent - before.bytesReceived) /
        wireBytes;
    const QString share = QStringLiteral("wire busy %1 of the time").arg(busy);
    qInfo().noquote() << share;
    if (fill)
        QVERIFY2(busy > 0.5, qPrintable(share)); // the in-process pacing by timers leaves gaps
    else
        QVERIFY2(busy < 0.3, qPrintable(share));
    for (const auto &spy : onceReads)
        QCOMPARE(spy->size(), 1);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestScheduler)

} // namespace tst_pollscheduler
#include "tst_pollscheduler.moc"
