#include "jointshape.h"

#include <cmath>

namespace tipscope::sim {

namespace {
constexpr double kEndK = 1.0; // closer than this, the controller alone brings the tip back
constexpr double kQuarterTurn = 1.5707963267948966;
} // namespace

JointShape::JointShape(int depthK, qint64 recoveryMs)
    : m_depthK(qBound(kMinDepthK, depthK, kMaxDepthK))
    , m_recoveryMs(qBound(qint64(kMinRecoveryMs), recoveryMs, qint64(kMaxRecoveryMs)))
    , m_dropMs(qBound(50.0, double(m_recoveryMs) / 4, 400.0)) {
    // Back at the band's edge `recovery` after leaving it: the rest of the drop on the way
    // down, τ·ln(depth/edge) on the way up.
    const double down = m_dropMs - leaveMs();
    m_tauMs = (double(m_recoveryMs) - down) / std::log(m_depthK / kEdgeK);
    m_endMs = m_dropMs + m_tauMs * std::log(m_depthK / kEndK);
}

double JointShape::belowTargetK(double ms) const {
    if (ms <= 0 || ms >= m_endMs)
        return 0;
    if (ms < m_dropMs) // a quarter sine: steep at first, round at the bottom
        return m_depthK * std::sin(kQuarterTurn * ms / m_dropMs);
    return m_depthK * std::exp(-(ms - m_dropMs) / m_tauMs);
}

double JointShape::leaveMs() const {
    return m_dropMs * std::asin(kEdgeK / m_depthK) / kQuarterTurn;
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

} // namespace tipscope::sim
