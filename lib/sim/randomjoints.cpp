#include "randomjoints.h"

#include "simstation.h"

namespace tipscope::sim {

RandomJoints::RandomJoints(SimStation *station, double perMinute, quint32 seed)
    : m_station(station)
    , m_meanGapMs(60'000.0 / qMax(0.01, perMinute))
    , m_random(seed) {
    // The ports start at random points of their first gap, not all at once.
    for (int port = 1; port <= m_station->portCount(); ++port) {
        m_nextMs.append(kRestMs + qint64(m_random.bounded(m_meanGapMs)));
        m_readySinceMs.append(-1);
    }
}

void RandomJoints::advance(int ms) {
    if (ms <= 0)
        return;
    m_ms += ms;
    for (int port = 1; port <= m_nextMs.size(); ++port) {
        // A port is ready once it could make a joint for kRestMs on end: settled at its
        // temperature after a heat-up, a wake or its last joint.
        qint64 &ready = m_readySinceMs[port - 1];
        if (!m_station->canMakeJoint(port))
            ready = -1;
        else if (ready < 0)
            ready = m_ms;
        if (m_ms >= m_nextMs.at(port - 1) && ready >= 0 && m_ms - ready >= kRestMs)
            makeJoint(port);
    }
}

void RandomJoints::makeJoint(int port) {
    const int depth = kMinDepthK + int(m_random.bounded(kMaxDepthK - kMinDepthK + 1));
    const int recovery =
        kMinRecoveryMs + int(m_random.bounded(kMaxRecoveryMs - kMinRecoveryMs + 1));
    m_station->startJoint(port, depth, recovery);
    // The same shape the station made, worn tip included: how long the port is busy.
    const JointShape made(depth, qRound64(recovery * (1 + m_station->port(port).wear)));
    const double gap = m_meanGapMs * (0.5 + m_random.generateDouble());
    m_nextMs[port - 1] = m_ms + qint64(qMax(gap, made.durationMs() + kRestMs));
    m_readySinceMs[port - 1] = -1;
}

} // namespace tipscope::sim
