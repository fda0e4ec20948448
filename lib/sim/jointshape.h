// JointShape: the course of one simulated solder joint, with the true values it was made from.
//
// The tip falls by depthK below the port's target over a short drop (a quarter of the recovery
// time, 50 to 400 ms; steep at first, round at the bottom), then comes back exponentially. The time
// constant is chosen so that the tip is back within kBandK of the target exactly recoveryMs after
// it left that band: the same definition of a recovery as the joint detector's
// (JointLimits::bandK), so the simulator's ground truth and what a client measures can be compared
// directly. The station reports whole degrees, so the band's edge as a reading shows it lies half a
// degree further out (kEdgeK): a tip at 344.6 °C reads 345 and is within 5 K of 350. The station's
// small wobble on the readings stays off while the joint lasts (SimStation::readLive()). The shape
// ends when the tip is within 1 K of the target; the station's controller does the rest. While the
// tip is held below the target the controller answers with power, as at the bench.
//
// Every joint the station makes, whoever asked for it (a command, the demo, the random joints),
// follows this one shape, so there is one physics of joints in the simulator.
#pragma once

#include <QMetaType>
#include <QString>
#include <QtGlobal>

namespace tipscope::sim {

// A joint as it was made: what `tipscope-sim` logs and tests compare against.
struct SimJoint {
    int port = 0;
    qint64 startMs = 0; // when the tip left the band (the line's time, see SimLine::jointMade)
    int depthK = 0;     // the lowest tip below the target
    qint64 recoveryMs = 0;
};

class JointShape {
public:
    static constexpr double kBandK = 5.0;
    static constexpr double kEdgeK = kBandK + 0.5;
    static constexpr int kMinDepthK = 6; // a shallower dip never leaves the band
    static constexpr int kMaxDepthK = 300;
    static constexpr int kMinRecoveryMs = 100;
    static constexpr int kMaxRecoveryMs = 20'000;

    // Values outside the limits above are clamped into them.
    JointShape(int depthK, qint64 recoveryMs);

    // How far below the target the tip is `ms` after the joint began.
    [[nodiscard]] double belowTargetK(double ms) const;
    [[nodiscard]] bool isOver(double ms) const { return ms >= m_endMs; }
    [[nodiscard]] double durationMs() const { return m_endMs; }
    // From the joint's beginning until the tip leaves the band.
    [[nodiscard]] double leaveMs() const;
    [[nodiscard]] int depthK() const { return int(m_depthK); }
    [[nodiscard]] qint64 recoveryMs() const { return m_recoveryMs; }

    // An English reason when a requested joint is outside the limits; empty when it is fine.
    [[nodiscard]] static QString checkRequest(int depthK, qint64 recoveryMs);

private:
    double m_depthK;
    qint64 m_recoveryMs;
    double m_dropMs;
    double m_tauMs;
    double m_endMs;
};

} // namespace tipscope::sim

Q_DECLARE_METATYPE(tipscope::sim::SimJoint)
