// RandomJoints: joints drawn from a shape set (JointShapeSet: "demo" by default, 15-100 K,
// recoveries 0.4-3 s) on every port of a station, about `perMinute` a minute on each, from a
// seeded generator (tipscope-sim --joints-per-minute), so a run can be repeated joint for joint.
// The port's wear lengthens the recoveries. A port gets a joint only once it could make one (at
// work, at its temperature, no joint in progress: SimStation::canMakeJoint()) for the set's rest
// on end, after a heat-up, a wake or its last joint, as a detector must see the tip settle first;
// so a high rate is a ceiling.
// Like DemoActivity it runs on the devices' simulated time.
#pragma once

#include "jointshapeset.h"

#include <QList>
#include <QRandomGenerator>

namespace tipscope::sim {

class SimStation;

class RandomJoints {
public:
    // The station must outlive the activity (the line owns both). The set's noise becomes the
    // station's.
    RandomJoints(SimStation *station, double perMinute, quint32 seed,
                 const JointShapeSet &shapes = *JointShapeSet::named(QStringLiteral("demo")));

    void advance(int ms);

private:
    void makeJoint(int port);

    SimStation *m_station;
    JointShapeSet m_shapes;
    double m_meanGapMs;
    QRandomGenerator m_random;
    qint64 m_ms = 0;
    QList<qint64> m_nextMs;       // per port, index port - 1
    QList<qint64> m_readySinceMs; // since when it could make a joint; -1: it cannot now
};

} // namespace tipscope::sim
