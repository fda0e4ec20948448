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
           a.powerIntegral == b.powerIntegral && a.verdict == b.verdict;
}

} // namespace tipscope::model
