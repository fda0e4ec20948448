#include "model/joints/jointdetector.h"

#include <cmath>

namespace tipscope::model {

namespace {
// The station reports whole degrees: a reading of setpoint − band is a tip anywhere above
// setpoint − band − 0.5, so that is where the continuous tip crosses the band's edge, and where
// both crossings are interpolated (see docs/protocol-notes.md).
constexpr double kWholeDegreeHalfStep = 0.5;

// When the straight line from (t0, v0) to (t1, v1) crosses `level`.
qint64 crossing(qint64 t0, double v0, qint64 t1, double v1, double level) {
    if (v1 == v0)
        return t1;
    const double f = qBound(0.0, (level - v0) / (v1 - v0), 1.0);
    return t0 + qint64(std::llround(f * double(t1 - t0)));
}
} // namespace

JointDetector::JointDetector(DeviceIdentity device, int port, JointLimits limits)
    : m_device(std::move(device))
    , m_port(port)
    , m_limits(limits) {}

double JointDetector::bandEdge(int setpoint) const {
    return double(setpoint) - m_limits.bandK - kWholeDegreeHalfStep;
}

bool JointDetector::sameConditions(const PortReading &reading) const {
    return m_last && reading.working && m_last->working && reading.setpoint == m_last->setpoint &&
           reading.tool == m_last->tool;
}

std::optional<JointRecord> JointDetector::add(const PortReading &reading) {
    if (!reading.tip)
        return gap(reading.timeMs);
    std::optional<JointRecord> ended;
    if (!sameConditions(reading)) {
        // Stand, sleep, heater off, another tool or setpoint: not a joint, and not one to finish.
        if (m_state == State::InJoint)
            ended = finish(m_last->timeMs, std::nullopt, false);
        m_state = State::Waiting;
    }
    const bool inBand = std::abs(*reading.tip - reading.setpoint) <= m_limits.bandK;
    switch (m_state) {
    case State::Waiting:
        if (inBand && reading.working) {
            m_state = State::Settled;
            m_settledSinceMs = reading.timeMs;
        }
        break;
    case State::Settled:
        if (*reading.tip < reading.setpoint - m_limits.bandK) {
            if (reading.timeMs - m_settledSinceMs >= kSettleMs && m_last && m_last->tip)
                startJoint(*m_last, reading);
            else
                m_state = State::Waiting; // left the band before it had settled
        } else if (!inBand) {
            m_state = State::Waiting; // above the band: the setpoint was lowered or it overshoots
        }
        break;
    case State::InJoint:
        accumulate(reading);
        if (*reading.tip >= reading.setpoint - m_limits.bandK) {
            const qint64 back = crossing(m_last->timeMs, *m_last->tip, reading.timeMs, *reading.tip,
                                         bandEdge(reading.setpoint));
            ended = finish(back, back, true);
            m_state = State::Settled;
            m_settledSinceMs = back;
        } else if (reading.timeMs - m_joint.startMs > kGiveUpMs) {
            ended = finish(reading.timeMs, std::nullopt, true);
            m_state = State::Waiting;
        }
        break;
    }
    m_last = reading;
    return ended;
}

std::optional<JointRecord> JointDetector::gap(qint64 timeMs) {
    std::optional<JointRecord> ended;
    if (m_state == State::InJoint)
        ended = finish(qMax(timeMs, m_last ? m_last->timeMs : timeMs), std::nullopt, false);
    m_state = State::Waiting;
    m_last.reset();
    return ended;
}

void JointDetector::startJoint(const PortReading &previous, const PortReading &reading) {
    m_state = State::InJoint;
    m_joint = JointRecord{};
    m_joint.device = m_device;
    m_joint.port = m_port;
    m_joint.tool = reading.tool;
    m_joint.setpoint = reading.setpoint;
    // A settled tip was flat at `previous`, and a joint draws heat at once: the drop is steep
    // from wherever between the readings it began. A straight line from the flat reading puts
    // the crossing too early when the drop is steep, so the crossing is no earlier than the
    // middle of the interval (where a departure at an unknown moment is expected); a gentle
    // slide out of the band keeps the straight line's later estimate.
    const qint64 straight = crossing(previous.timeMs, *previous.tip, reading.timeMs, *reading.tip,
                                     bandEdge(reading.setpoint));
    m_joint.startMs = qMax(straight, previous.timeMs + (reading.timeMs - previous.timeMs) / 2);
    m_joint.lowestTip = *previous.tip;
    m_joint.powerPeak = int(std::lround(previous.powerPct));
    accumulate(reading);
}

// The lowest tip, the power peak, and the power-time integral by the trapezoid rule.
void JointDetector::accumulate(const PortReading &reading) {
    m_joint.lowestTip = qMin(m_joint.lowestTip, *reading.tip);
    m_joint.powerPeak = qMax(m_joint.powerPeak, int(std::lround(reading.powerPct)));
    if (m_last) {
        const qint64 from = qMax(m_last->timeMs, m_joint.startMs);
        if (reading.timeMs > from)
            m_joint.powerIntegral +=
                (m_last->powerPct + reading.powerPct) / 2 * double(reading.timeMs - from) / 1000;
    }
}

JointRecord JointDetector::finish(qint64 endMs, std::optional<qint64> recoveredAtMs,
                                  bool complete) {
    JointRecord j = m_joint;
    j.endMs = qMax(endMs, j.startMs);
    j.durationMs = j.endMs - j.startMs;
    j.dipDepth = j.setpoint - j.lowestTip;
    if (recoveredAtMs)
        j.recoveryMs = *recoveredAtMs - j.startMs;
    j.verdict = complete ? judge(j, m_limits) : JointVerdict::Incomplete;
    return j;
}

JointVerdict JointDetector::judge(const JointRecord &joint, const JointLimits &limits) {
    if (joint.dipDepth > limits.maxDipK)
        return JointVerdict::TooDeep;
    if (!joint.recoveryMs || *joint.recoveryMs > limits.maxRecoveryMs)
        return JointVerdict::SlowRecovery;
    return JointVerdict::Ok;
}

} // namespace tipscope::model
