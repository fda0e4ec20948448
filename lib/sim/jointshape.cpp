#include "jointshape.h"

#include <cmath>

namespace tipscope::sim {

namespace {
constexpr double kEndK = 1.0; // closer than this, the controller alone brings the tip back
constexpr double kQuarterTurn = 1.5707963267948966;
constexpr double kMinRiseMs = 50; // the rise from the band's edge back is never shorter
} // namespace

JointShape::JointShape(int depthK, qint64 recoveryMs)
    : JointShape(JointSpec{depthK, recoveryMs}) {}

JointShape::JointShape(const SimJoint &made)
    : JointShape(JointSpec{made.depthK, made.recoveryMs, made.dropMs, made.form, made.overshootK}) {
}

JointShape::JointShape(const JointSpec &spec)
    : m_depthK(qBound(kMinDepthK, spec.depthK, kMaxDepthK))
    , m_recoveryMs(qBound(qint64(kMinRecoveryMs), spec.recoveryMs, qint64(kMaxRecoveryMs)))
    , m_dropMs(
          qBound(kMinDropMs, spec.dropMs > 0 ? spec.dropMs : double(m_recoveryMs) / 4, kMaxDropMs))
    , m_form(spec.form)
    , m_overshootK(qBound(0.0, spec.overshootK, kMaxOvershootK)) {
    // Back at the band's edge `recovery` after leaving it: the rest of the drop on the way down,
    // the rise from the bottom to the edge on the way up. A recovery too short for the drop asked
    // for is lengthened, so the truth logged is the joint made.
    const double down = m_dropMs - leaveMs();
    m_recoveryMs = qMax(m_recoveryMs, qint64(std::ceil(down + kMinRiseMs)));
    const double rise = double(m_recoveryMs) - down;
    if (m_form == RecoveryForm::Exponential) {
        m_riseMs = rise / std::log(m_depthK / kEdgeK);
        m_backMs = m_dropMs + m_riseMs * std::log(m_depthK / kEndK);
    } else {
        m_riseMs = rise * m_depthK / (m_depthK - kEdgeK);
        m_backMs = m_dropMs + m_riseMs * (m_depthK - kEndK) / m_depthK;
    }
    m_endMs = m_backMs + (m_overshootK > 0 ? kOvershootMs : 0);
}

double JointShape::mainBelowTargetK(double ms) const {
    if (ms < m_dropMs) // a quarter sine: steep at first, round at the bottom
        return m_depthK * std::sin(kQuarterTurn * ms / m_dropMs);
    if (m_form == RecoveryForm::Exponential)
        return m_depthK * std::exp(-(ms - m_dropMs) / m_riseMs);
    return m_depthK * (1 - (ms - m_dropMs) / m_riseMs);
}

double JointShape::belowTargetK(double ms) const {
    if (ms <= 0 || ms >= m_endMs)
        return 0;
    if (ms < m_backMs)
        return mainBelowTargetK(ms);
    // From 1 K below the target up through it to the overshoot and back: negative is above.
    const double u = (ms - m_backMs) / kOvershootMs;
    return kEndK * (1 - u) - m_overshootK * std::sin(2 * kQuarterTurn * u);
}

double JointShape::leaveMs() const {
    return m_dropMs * std::asin(kEdgeK / m_depthK) / kQuarterTurn;
}

SimJoint JointShape::made(int port, qint64 beganMs) const {
    return SimJoint{
        port,        beganMs + qRound64(leaveMs()), depthK(), m_recoveryMs, m_dropMs, m_form,
        m_overshootK};
}

QString JointShape::checkRequest(int depthK, qint64 recoveryMs) {
    if (depthK < kMinDepthK || depthK > kMaxDepthK)
        return QStringLiteral("depth must be %1 to %2 K").arg(kMinDepthK).arg(kMaxDepthK);
    if (recoveryMs < kMinRecoveryMs || recoveryMs > kMaxRecoveryMs)
        return QStringLiteral("recovery must be %1 to %2 ms")
            .arg(kMinRecoveryMs)
            .arg(kMaxRecoveryMs);
    return {};
}

QString recoveryFormName(RecoveryForm form) {
    return form == RecoveryForm::Linear ? QStringLiteral("linear") : QStringLiteral("exponential");
}

} // namespace tipscope::sim
