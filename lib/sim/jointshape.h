// JointShape: the course of one simulated solder joint, with the true values it was made from.
//
// The tip falls by depthK below the port's target over a drop of 50 to 400 ms (by default a
// quarter of the recovery time; steep at first, round at the bottom), then comes back,
// exponentially or along a straight line, and may overshoot the target a little before it
// settles. The recovery is chosen so that the tip is back within kBandK of the target exactly
// recoveryMs after it left that band: the same definition of a recovery as the joint detector's
// (JointLimits::bandK), so the simulator's ground truth and what a client measures can be compared
// directly. The station reports whole degrees, so the band's edge as a reading shows it lies half a
// degree further out (kEdgeK): a tip at 344.6 °C reads 345 and is within 5 K of 350. The shape
// ends when the tip is within 1 K of the target (after the overshoot, if any); the station's
// controller does the rest. While the tip is held below the target the controller answers with
// power, as at the bench.
//
// Every joint the station makes, whoever asked for it (a command, the demo, the random joints),
// follows this one shape, so there is one physics of joints in the simulator.
#pragma once

#include <QMetaType>
#include <QString>
#include <QtGlobal>

namespace tipscope::sim {

enum class RecoveryForm { Exponential, Linear };

// How far a settled tip's readings wobble on the demo's station (±K, between joints only).
inline constexpr double kDemoWobbleK = 0.6;

// What a joint is asked to be. Values outside JointShape's limits are clamped into them.
struct JointSpec {
    int depthK = 0;
    qint64 recoveryMs = 0;
    double dropMs = 0; // 0: a quarter of the recovery
    RecoveryForm form = RecoveryForm::Exponential;
    double overshootK = 0; // how far above the target the tip swings once back
};

// A joint as it was made: what `tipscope-sim` logs and tests compare against.
struct SimJoint {
    int port = 0;
    qint64 startMs = 0; // when the tip left the band (the line's time, see SimLine::jointMade)
    int depthK = 0;     // the lowest tip below the target
    qint64 recoveryMs = 0;
    double dropMs = 0; // from the joint's beginning to its lowest point
    RecoveryForm form = RecoveryForm::Exponential;
    double overshootK = 0;
    // Known once the joint is over (SimLine::jointEnded): how many times its tip was read, and
    // how deep the tip truly was at the deepest of those instants. A client that knew the true
    // tip at its own sample instants would report that depth: what sampling alone costs.
    int reads = 0;
    double readDepthK = 0;
};

class JointShape {
public:
    static constexpr double kBandK = 5.0;
    static constexpr double kEdgeK = kBandK + 0.5;
    static constexpr int kMinDepthK = 6; // a shallower dip never leaves the band
    static constexpr int kMaxDepthK = 300;
    static constexpr int kMinRecoveryMs = 100;
    static constexpr int kMaxRecoveryMs = 20'000;
    static constexpr double kMinDropMs = 50;
    static constexpr double kMaxDropMs = 400;
    static constexpr double kMaxOvershootK = 4; // stays within the band
    static constexpr double kOvershootMs = 800; // the swing above the target and back

    // Values outside the limits above are clamped into them.
    JointShape(int depthK, qint64 recoveryMs);
    explicit JointShape(const JointSpec &spec);
    // The shape a logged joint was made with.
    explicit JointShape(const SimJoint &made);

    // How far below the target the tip is `ms` after the joint began.
    [[nodiscard]] double belowTargetK(double ms) const;
    [[nodiscard]] bool isOver(double ms) const { return ms >= m_endMs; }
    [[nodiscard]] double durationMs() const { return m_endMs; }
    // From the joint's beginning until the tip leaves the band.
    [[nodiscard]] double leaveMs() const;
    [[nodiscard]] int depthK() const { return int(m_depthK); }
    [[nodiscard]] qint64 recoveryMs() const { return m_recoveryMs; }
    [[nodiscard]] double dropMs() const { return m_dropMs; }
    [[nodiscard]] RecoveryForm form() const { return m_form; }
    [[nodiscard]] double overshootK() const { return m_overshootK; }
    // The record of this shape begun at `beganMs` (the line's time) on `port`.
    [[nodiscard]] SimJoint made(int port, qint64 beganMs) const;

    // An English reason when a requested joint is outside the limits; empty when it is fine.
    [[nodiscard]] static QString checkRequest(int depthK, qint64 recoveryMs);

private:
    [[nodiscard]] double mainBelowTargetK(double ms) const;

    double m_depthK;
    qint64 m_recoveryMs;
    double m_dropMs;
    RecoveryForm m_form;
    double m_overshootK;
    double m_riseMs = 0; // exponential: the time constant; linear: the time from depth to 0
    double m_backMs = 0; // when the rise reaches kEndK (then the overshoot, if any)
    double m_endMs = 0;
};

[[nodiscard]] QString recoveryFormName(RecoveryForm form);

} // namespace tipscope::sim

Q_DECLARE_METATYPE(tipscope::sim::SimJoint)
