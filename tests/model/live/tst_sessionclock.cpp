// SessionClock stamps samples and events: it starts at the wall clock and runs on the monotonic
// one, ignores the wall clock set back, catches up when the wall clock runs ahead (the computer
// slept and the monotonic clock stood still), and never goes backwards.
#include "model/live/sessionclock.h"
#include "testmain.h"

#include <QDateTime>
#include <QTest>

namespace tst_sessionclock {

using tipscope::model::SessionClock;

namespace {
constexpr qint64 kStart = 1'700'000'000'000;

struct FakeClocks {
    qint64 wall = kStart;
    qint64 monotonic = 5'000;
    void pass(qint64 ms) {
        wall += ms;
        monotonic += ms;
    }
    [[nodiscard]] SessionClock clock() {
        return SessionClock([this] { return wall; }, [this] { return monotonic; });
    }
};
} // namespace

class TestSessionClock : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void startsAtTheWallClockAndRunsWithTime();
    void aWallClockSetBackIsIgnored();
    void afterASleepItCatchesUpWithTheWallClock();
    void aWallClockAMomentAheadIsNoSleep();
    void theSystemClockNeverGoesBackwards();
};

void TestSessionClock::startsAtTheWallClockAndRunsWithTime() {
    FakeClocks c;
    SessionClock clock = c.clock();
    QCOMPARE(clock.nowMs(), kStart);
    c.pass(1234);
    QCOMPARE(clock.nowMs(), kStart + 1234);
}

void TestSessionClock::aWallClockSetBackIsIgnored() {
    FakeClocks c;
    SessionClock clock = c.clock();
    c.pass(10'000);
    c.wall -= 3600'000; // set back an hour
    QCOMPARE(clock.nowMs(), kStart + 10'000);
    c.pass(500);
    QCOMPARE(clock.nowMs(), kStart + 10'500);
}

void TestSessionClock::afterASleepItCatchesUpWithTheWallClock() {
    FakeClocks c;
    SessionClock clock = c.clock();
    c.pass(10'000);
    c.wall += 600'000; // ten minutes asleep: only the wall clock moved
    QCOMPARE(clock.nowMs(), kStart + 610'000);
    c.pass(100);
    QCOMPARE(clock.nowMs(), kStart + 610'100); // and runs on from there
}

void TestSessionClock::aWallClockAMomentAheadIsNoSleep() {
    FakeClocks c;
    SessionClock clock = c.clock();
    c.wall += SessionClock::kCatchUpMs; // an NTP slew, scheduling noise
    QCOMPARE(clock.nowMs(), kStart);
}

void TestSessionClock::theSystemClockNeverGoesBackwards() {
    SessionClock clock;
    const qint64 wall = QDateTime::currentMSecsSinceEpoch();
    qint64 previous = clock.nowMs();
    QVERIFY(qAbs(previous - wall) < 1000);
    for (int i = 0; i < 2000; ++i) {
        const qint64 now = clock.nowMs();
        QVERIFY(now >= previous);
        previous = now;
    }
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSessionClock)

} // namespace tst_sessionclock
#include "tst_sessionclock.moc"
