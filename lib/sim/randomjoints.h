// RandomJoints: joints of varied depth and recovery on every port of a station, about
// `perMinute` a minute on each, from a seeded generator (tipscope-sim --joints-per-minute), so a
// run can be repeated joint for joint. Depths are 15 to 100 K, recoveries 0.4 to 3 s before the
// port's wear lengthens them. A port gets a joint only once it could make one (at work, at its
// temperature, no joint in progress: SimStation::canMakeJoint()) for kRestMs on end, after a
// heat-up, a wake or its last joint, as a detector must see the tip settle first; so a high rate
// is a ceiling.
// Like DemoActivity it runs on the devices' simulated time.
#pragma once

#include <QList>
#include <QRandomGenerator>

namespace tipscope::sim {

class SimStation;

class RandomJoints {
public:
    static constexpr int kMinDepthK = 15;
    static constexpr int kMaxDepthK = 100;
    static constexpr int kMinRecoveryMs = 400;
    static constexpr int kMaxRecoveryMs = 3000;
    static constexpr int kRestMs = 3000;

    // The station must outlive the activity (the line owns both).
    RandomJoints(SimStation *station, double perMinute, quint32 seed);

    void advance(int ms);

private:
    void makeJoint(int port);

    SimStation *m_station;
    double m_meanGapMs;
    QRandomGenerator m_random;
    qint64 m_ms = 0;
    QList<qint64> m_nextMs;       // per port, index port - 1
    QList<qint64> m_readySinceMs; // since when it could make a joint; -1: it cannot now
};

} // namespace tipscope::sim
