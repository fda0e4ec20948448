// SessionClock: the time that stamps a session's samples and events, in milliseconds since the
// epoch. It runs on the monotonic clock, so a wall clock set back never makes new samples look
// older than earlier ones. When the wall clock runs ahead of it by more than kCatchUpMs, it
// catches up. That happens when the computer slept, because the monotonic clock stands still
// then. The sleep then shows as a gap at the right time, and the samples after it keep their
// real times. It never goes backwards.
#pragma once

#include <QtGlobal>
#include <functional>

namespace tipscope::model {

class SessionClock {
public:
    using Source = std::function<qint64()>; // milliseconds
    static constexpr qint64 kCatchUpMs = 2000;

    // The system's wall clock and monotonic clock.
    SessionClock();
    // For tests: any two sources, the monotonic one never going back.
    SessionClock(Source wallMs, Source monotonicMs);

    [[nodiscard]] qint64 nowMs();

private:
    Source m_wallMs;
    Source m_monotonicMs;
    qint64 m_offsetMs = 0; // the session's time is the monotonic clock plus this
};

} // namespace tipscope::model
