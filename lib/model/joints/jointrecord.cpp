#include "jointrecord.h"

namespace tipscope::model {

QString jointVerdictName(JointVerdict verdict) {
    switch (verdict) {
    case JointVerdict::Ok:
        return QStringLiteral("ok");
    case JointVerdict::SlowRecovery:
        return QStringLiteral("slow recovery");
    case JointVerdict::TooDeep:
        return QStringLiteral("too deep");
    case JointVerdict::Incomplete:
        return QStringLiteral("incomplete");
    }
    return {};
}

std::optional<JointVerdict> jointVerdictFromName(const QString &name) {
    for (const JointVerdict verdict : kJointVerdicts) {
        if (jointVerdictName(verdict) == name)
            return verdict;
    }
    return std::nullopt;
}

bool operator==(const JointRecord &a, const JointRecord &b) {
    return a.device == b.device && a.port == b.port && a.tool == b.tool && a.startMs == b.startMs &&
           a.endMs == b.endMs && a.setpoint == b.setpoint && a.lowestTip == b.lowestTip &&
           a.dipDepth == b.dipDepth && a.recoveryMs == b.recoveryMs &&
           a.durationMs == b.durationMs && a.powerPeak == b.powerPeak &&
           a.powerIntegral == b.powerIntegral && a.verdict == b.verdict &&
           a.startUncertaintyMs == b.startUncertaintyMs && a.dipUncertaintyK == b.dipUncertaintyK &&
           a.recoveryUncertaintyMs == b.recoveryUncertaintyMs &&
           a.recoveryBounded == b.recoveryBounded && a.limits == b.limits;
}

QString recoveryWords(const JointRecord &joint) {
    if (!joint.recoveryMs)
        return QStringLiteral("-");
    const qint64 ms = *joint.recoveryMs;
    if (joint.recoveryBounded)
        return QStringLiteral("%1-%2 s bounded")
            .arg(QString::number(double(qMax<qint64>(0, ms - joint.recoveryUncertaintyMs)) / 1000,
                                 'f', 1),
                 QString::number(double(ms + joint.recoveryUncertaintyMs) / 1000, 'f', 1));
    return QString::number(double(ms) / 1000, 'f', 2) + QStringLiteral(" s");
}

} // namespace tipscope::model
