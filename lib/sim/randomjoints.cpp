#include "randomjoints.h"

#include "simstation.h"

namespace tipscope::sim {

RandomJoints::RandomJoints(SimStation *station, double perMinute, quint32 seed,
                           const JointShapeSet &shapes)
    : m_station(station)
    , m_shapes(shapes)
    , m_meanGapMs(60'000.0 / qMax(0.01, perMinute))
    , m_random(seed) {
    m_station->setReadingNoise(m_shapes.noiseK, m_shapes.noiseDuringJoints);
    // The ports start at random points of their first gap, not all at once.
    for (int port = 1; port <= m_station->portCount(); ++port) {
        m_nextMs.append(m_shapes.restMs + qint64(m_random.bounded(m_meanGapMs)));
        m_readySinceMs.append(-1);
    }
}

void RandomJoints::advance(int ms) {
    if (ms <= 0)
        return;
    m_ms += ms;
    for (int port = 1; port <= m_nextMs.size(); ++port) {
        // A port is ready once it could make a joint for the set's rest on end: settled at its
        // temperature after a heat-up, a wake or its last joint.
        qint64 &ready = m_readySinceMs[port - 1];
        if (!m_station->canMakeJoint(port))
            ready = -1;
        else if (ready < 0)
            ready = m_ms;
        if (m_ms >= m_nextMs.at(port - 1) && ready >= 0 && m_ms - ready >= m_shapes.restMs)
            makeJoint(port);
    }
}

void RandomJoints::makeJoint(int port) {
    const auto made = m_station->startJoint(port, m_shapes.draw(m_random));
    // How long the port is busy: the shape the station made, worn tip included.
    const double busyMs = made ? JointShape(*made).durationMs() : 0;
    const double gap = m_meanGapMs * (0.5 + m_random.generateDouble());
    m_nextMs[port - 1] = m_ms + qint64(qMax(gap, busyMs + m_shapes.restMs));
    m_readySinceMs[port - 1] = -1;
}

} // namespace tipscope::sim
