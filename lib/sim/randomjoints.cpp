#include "randomjoints.h"

#include "simstation.h"

namespace tipscope::sim {

RandomJoints::RandomJoints(SimStation *station, double perMinute, quint32 seed)
    : m_station(station)
    , m_meanGapMs(60'000.0 / qMax(0.01, perMinute))
    , m_random(seed) {
    // The ports start at random points of their first gap, not all at once.
    for (int port = 1; port <= m_station->portCount(); ++port)
        m_nextMs.append(kRestMs + qint64(m_random.bounded(m_meanGapMs)));
}

void RandomJoints::advance(int ms) {
    if (ms <= 0)
        return;
    m_ms += ms;
    for (int port = 1; port <= m_nextMs.size(); ++port) {
        if (m_ms < m_nextMs.at(port - 1))
            continue;
        if (m_station->canMakeJoint(port))
            makeJoint(port);
        else
            m_nextMs[port - 1] = m_ms + kRestMs;
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
}

} // namespace tipscope::sim
