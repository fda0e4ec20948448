// Waiting in a test as the application waits: in a real event loop, whose timers fire on time.
//
// Qt Test's qWait() and QTRY_* poll the events and then sleep up to 10 ms between polls, so a
// timer comes due up to 10 ms late. A line paced by timers in the same thread (the demo's
// simulated wire) then carries about 49 transactions a second instead of its 70: a test that
// judges the wire's pace must wait with these instead.
#pragma once

#include <QEventLoop>
#include <QTimer>

#include <functional>

namespace tipscope::testing {

inline void runFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// Runs the event loop until `done` holds (checked every 20 ms) or `timeoutMs` passed; whether it
// holds.
inline bool runUntil(const std::function<bool()> &done, int timeoutMs) {
    if (done())
        return true;
    QEventLoop loop;
    QTimer check;
    QObject::connect(&check, &QTimer::timeout, &loop, [&] {
        if (done())
            loop.quit();
    });
    check.start(20);
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    loop.exec();
    return done();
}

} // namespace tipscope::testing
