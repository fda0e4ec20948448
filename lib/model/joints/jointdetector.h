// JointDetector: turns one port's readings, as they arrive, into joint records.
//
// A joint is a dip of the tip temperature while the port works at a steady setpoint: the tip
// leaves the band below the setpoint (the solder and the board draw heat), the heater answers
// with power, and the tip comes back. The detector is a small state machine per port:
//
//   waiting  → settled   the tip has stayed within the band for kSettleMs while working at one
//                        setpoint and with one tool (a heat-up or a wake from sleep is never a
//                        joint: the tip has not settled yet);
//   settled  → in joint  a reading below the band; the joint starts where the tip crossed the
//                        band's lower edge (interpolated between the two readings around it);
//   in joint → settled   the tip is back within the band: the recovery time runs from start to
//                        that crossing, also interpolated, so it is finer than the poll period.
//
// Whatever breaks the measurement during a joint ends it as Incomplete, with what was seen so
// far: a gap in the readings (gap(), or a reading without a tip value), the port leaving work
// (stand, sleep, heater off), another tool, or another setpoint. A joint that has not recovered
// after kGiveUpMs ends as SlowRecovery without a recovery time. Each end is followed by waiting
// again. Judging: TooDeep when the dip exceeds the limit, else SlowRecovery when the recovery
// took longer than the limit, else Ok.
//
// Plain computation, no timers and no Qt objects: the GUI, the CLI, the line service and the
// bench feed it the same readings and get the same joints.
#pragma once

#include "model/joints/jointrecord.h"

#include <QList>

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

    JointDetector(DeviceIdentity device, int port, JointLimits limits = {});

    void setLimits(const JointLimits &limits) { m_limits = limits; }
    [[nodiscard]] const JointLimits &limits() const { return m_limits; }

    // Feeds one reading (in time order); returns the joint it ended, if any.
    [[nodiscard]] std::optional<JointRecord> add(const PortReading &reading);
    // The readings stopped at `timeMs` (line down, no answer): a joint in progress ends
    // Incomplete, and the port must settle again.
    [[nodiscard]] std::optional<JointRecord> gap(qint64 timeMs);
    [[nodiscard]] bool inJoint() const { return m_state == State::InJoint; }

    [[nodiscard]] static JointVerdict judge(const JointRecord &joint, const JointLimits &limits);

private:
    enum class State { Waiting, Settled, InJoint };

    void startJoint(const PortReading &previous, const PortReading &reading);
    void accumulate(const PortReading &reading);
    [[nodiscard]] JointRecord finish(qint64 endMs, std::optional<qint64> recoveredAtMs,
                                     bool complete);
    [[nodiscard]] double bandEdge(int setpoint) const;
    [[nodiscard]] bool sameConditions(const PortReading &reading) const;

    DeviceIdentity m_device;
    int m_port;
    JointLimits m_limits;
    State m_state = State::Waiting;
    std::optional<PortReading> m_last;
    qint64 m_settledSinceMs = 0;
    JointRecord m_joint;
};

} // namespace tipscope::model
