#include "demoactivity.h"

#include "simfeeder.h"
#include "simstation.h"

namespace tipscope::sim {

namespace {
constexpr int kJointPort = 1;
constexpr int kRestingPort = 2;
constexpr int kWorking = 0;
constexpr int kStand = 1;
} // namespace

DemoActivity::DemoActivity(SimStation *station, SimFeeder *feeder)
    : m_station(station)
    , m_feeder(feeder) {}

bool DemoActivity::passed(int ms, qint64 offset, qint64 period) const {
    const auto count = [&](qint64 t) { return t < offset ? 0 : (t - offset) / period + 1; };
    return count(m_ms) > count(m_ms - ms);
}

bool DemoActivity::portInUse(int port) const {
    if (!m_station || m_station->portCount() < port)
        return false;
    const SimPort &p = m_station->port(port);
    return p.tool != 0 && p.error == 0;
}

void DemoActivity::advance(int ms) {
    if (ms <= 0)
        return;
    m_ms += ms;
    if (portInUse(kJointPort) && m_station->port(kJointPort).status == kWorking &&
        passed(ms, kJointOffsetMs, kJointEveryMs))
        m_station->startJoint(kJointPort, kJointDepthK, kJointRecoveryMs);
    // Ends before starts: a tick long enough to hold both must not leave a start running.
    if (m_resting && passed(ms, kRestCycleMs, kRestCycleMs)) {
        m_resting = false;
        if (portInUse(kRestingPort) && m_station->port(kRestingPort).status != kWorking)
            m_station->setStatus(kRestingPort, kWorking);
    }
    if (portInUse(kRestingPort) && passed(ms, kRestStartMs, kRestCycleMs) &&
        m_station->port(kRestingPort).status == kWorking) {
        m_station->setStatus(kRestingPort, kStand);
        m_resting = true;
    }
    const bool feedEnds = passed(ms, kFeedOffsetMs + kFeedMs, kFeedEveryMs);
    if (m_feeding && feedEnds) {
        m_feeding = false;
        m_feeder->stopFeed();
    }
    if (m_feeder && m_feeder->error() == 0 && !m_feeder->isFeeding() && !feedEnds &&
        passed(ms, kFeedOffsetMs, kFeedEveryMs)) {
        m_feeder->startFeed();
        m_feeding = true;
    }
}

} // namespace tipscope::sim
