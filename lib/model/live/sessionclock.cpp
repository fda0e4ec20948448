#include "sessionclock.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <memory>

namespace tipscope::model {

namespace {
SessionClock::Source systemMonotonic() {
    auto timer = std::make_shared<QElapsedTimer>();
    timer->start();
    return [timer] { return timer->elapsed(); };
}
} // namespace

SessionClock::SessionClock()
    : SessionClock([] { return QDateTime::currentMSecsSinceEpoch(); }, systemMonotonic()) {}

SessionClock::SessionClock(Source wallMs, Source monotonicMs)
    : m_wallMs(std::move(wallMs))
    , m_monotonicMs(std::move(monotonicMs))
    , m_offsetMs(m_wallMs() - m_monotonicMs()) {}

qint64 SessionClock::nowMs() {
    const qint64 now = m_monotonicMs() + m_offsetMs;
    const qint64 wall = m_wallMs();
    if (wall > now + kCatchUpMs) {
        m_offsetMs += wall - now;
        return wall;
    }
    return now;
}

} // namespace tipscope::model
