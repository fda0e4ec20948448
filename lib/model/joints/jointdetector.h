// JointDetector: turns one port's readings, as they arrive, into joint records.
//
// A joint is a dip of the tip temperature while the port works at a steady setpoint: the tip
// leaves the band below the setpoint (the solder and the board draw heat), the heater answers
// with power, and the tip comes back. The detector is a small state machine per port:
//
//   waiting  → settled   the tip has stayed within the band for kSettleMs while working at one
//                        setpoint and with one tool (a heat-up or a wake from sleep is never a
//                        joint: the tip has not settled yet);
//   settled  → in joint  a reading below the band; the next joint may begin at once after a
//                        recovery (joints follow each other within a second on a busy port);
//   in joint → settled   kConfirmReadings readings in a row back within the band (one may be the
//                        wobble of a tip still on its way), then the readings after the return
//                        that its fit needs (at most kMaxTailMs; a new dip ends them at once).
//
// The figures come from all the readings around each event, not from the two that bracket it
// (jointfit.h): the start is where a line through the first readings of the fall crosses the
// band's edge, within the last reading before it; the lowest point is the vertex of a parabola
// through the lowest readings; the recovery is where a first-order return fitted through the
// whole climb crosses the edge when the readings follow one, else a line through it when they
// climb straight, else a local fit through the readings around the return (a wider one on both
// sides when they wobble). Each carries its uncertainty, across both the fit's crossing and the
// readings around the return where the two disagree; a recovery whose readings are too far apart
// to place it within kMeasuredWithinMs is only bounded (between the readings around it).
//
// Whatever breaks the measurement during a joint ends it: a gap in the readings, the port
// leaving work (stand, sleep, heater off), another tool or setpoint. If the heater had answered
// (its power rose by kPowerRisePct), a joint was under way: it ends Incomplete, with what was seen
// so far; if not, the tip fell because the heater was idle (a tool put in its stand and asleep,
// an open circuit cooling down), which is an event of the port, never a joint. A joint that has
// not recovered after kGiveUpMs ends as SlowRecovery without a recovery time. Judging: TooDeep
// when the dip exceeds the limit, else SlowRecovery when the recovery took longer than the limit,
// else Ok; a bounded recovery that may lie on either side of the limit is not judged (Incomplete).
//
// Plain computation, no timers and no Qt objects: the GUI, the CLI, the line service and the
// bench feed it the same readings and get the same joints.
#pragma once

#include "model/joints/jointfit.h"
#include "model/joints/jointrecord.h"

#include <QList>
#include <deque>
#include <vector>

namespace tipscope::model {

struct JointLimits {
    int bandK = 5;               // within this of the setpoint the tip counts as recovered
    qint64 maxRecoveryMs = 5000; // slower is SlowRecovery
    int maxDipK = 80;            // deeper is TooDeep
    // A tool's recent recoveries slower than its first ones by more than this share: tip wear.
    double wearShare = 0.3;

    friend bool operator==(const JointLimits &a, const JointLimits &b) {
        return a.bandK == b.bandK && a.maxRecoveryMs == b.maxRecoveryMs && a.maxDipK == b.maxDipK &&
               a.wearShare == b.wearShare;
    }
};

// One reading of a port, in wire units (°C, %); tip empty when the read got no answer.
struct PortReading {
    qint64 timeMs = 0;
    std::optional<int> tip;
    int setpoint = 0;
    double powerPct = 0;
    bool working = true; // the port's status is "working" (not stand, sleep, off)
    QString tool;
};

class JointDetector {
public:
    static constexpr qint64 kSettleMs = 2000;
    static constexpr qint64 kGiveUpMs = 30'000;
    static constexpr int kConfirmReadings = 2;
    static constexpr double kPowerRisePct = 10;
    static constexpr qint64 kMeasuredWithinMs = 250;
    // The longest a recovered joint waits for readings after its return before it is reported.
    static constexpr qint64 kMaxTailMs = 1500;
    // A dip whose deepest reading lies less than this beyond the band is the readings'
    // wobble, not a joint (the shallowest joints measured are 10 K deep).
    static constexpr double kMinExcessK = 3;

    JointDetector(DeviceIdentity device, int port, JointLimits limits = {});

    void setLimits(const JointLimits &limits) { m_limits = limits; }
    [[nodiscard]] const JointLimits &limits() const { return m_limits; }

    // Feeds one reading (in time order); returns the joint it ended, if any.
    [[nodiscard]] std::optional<JointRecord> add(const PortReading &reading);
    // The readings stopped at `timeMs` (line down, no answer): a joint in progress ends
    // Incomplete, and the port must settle again.
    [[nodiscard]] std::optional<JointRecord> gap(qint64 timeMs);
    [[nodiscard]] bool inJoint() const { return m_state == State::InJoint; }
    // The earliest the open joint's start can be (the last reading within the band before it;
    // its estimate lies after it); none outside a joint.
    [[nodiscard]] std::optional<qint64> openSinceMs() const {
        return inJoint() && !m_readings.empty() ? std::optional<qint64>(m_readings.front().timeMs)
                                                : std::nullopt;
    }

    [[nodiscard]] static JointVerdict judge(const JointRecord &joint, const JointLimits &limits);

private:
    enum class State { Waiting, Settled, InJoint };
    // How a joint ended.
    enum class End { Recovered, GaveUp, Broken };

    void startJoint(const PortReading &previous, const PortReading &reading);
    void accumulate(const PortReading &reading);
    // The joint as it ends; none when the heater never answered (not a joint, see above).
    [[nodiscard]] std::optional<JointRecord> finish(End end, qint64 endMs);
    void estimateStart(JointRecord &joint) const;
    void estimateLowest(JointRecord &joint) const;
    [[nodiscard]] std::optional<double> vertexDepth(size_t low) const;
    void estimateRecovery(JointRecord &joint) const;
    struct Return {
        size_t back = 0; // the first reading of the run back in the band; 0: none
        size_t low = 0;
        double straightMs = 0;
        double halfWindowMs = 0;
    };
    [[nodiscard]] Return returnOf() const;
    [[nodiscard]] qint64 tailUntil() const;
    [[nodiscard]] std::optional<Approach> approachOf(const Return &r) const;
    struct Crossing {
        double timeMs = 0;
        double uncertaintyMs = 0;
    };
    [[nodiscard]] std::optional<Crossing> straightClimbOf(const Return &r) const;
    [[nodiscard]] double wobbleReachK() const;
    [[nodiscard]] bool withinWobble(double sigma, int count) const;
    [[nodiscard]] bool nearTheReturn(const Return &r, double crossingMs, double slopePerMs) const;
    void settleAfterRecovery(qint64 timeMs);
    [[nodiscard]] double bandEdge() const;
    [[nodiscard]] bool inBand(const PortReading &reading) const;
    [[nodiscard]] bool sameConditions(const PortReading &reading) const;

    DeviceIdentity m_device;
    int m_port;
    JointLimits m_limits;
    State m_state = State::Waiting;
    std::optional<PortReading> m_last;
    qint64 m_settledSinceMs = 0;
    bool m_justRecovered = false; // settled by a recovery: the next dip is a joint at once
    JointRecord m_joint;
    // The joint's readings: the last one within the band before it, then every one since.
    std::vector<PortReading> m_readings;
    double m_restingPowerPct = 0;
    // The settled tip's last readings before a joint, and their scatter about their mean when the
    // joint began (K, never below rounding's): how far any reading of this port may be off.
    std::deque<int> m_restingTips;
    double m_restingSigmaK = 0;
    int m_backInBand = 0; // readings in a row within the band since the last one below it
    // Set once the return is confirmed: until then the readings after it are gathered.
    std::optional<qint64> m_tailUntilMs;
};

} // namespace tipscope::model
