// JointRecord: one solder joint as the joint detector measured and judged it. A plain value.
//
// Units are the wire's: times in milliseconds since the epoch (UTC), temperatures in °C, power
// in %, durations in milliseconds, the power-time integral in %·s. The dip depth is how far the
// tip fell below the setpoint (setpoint minus the lowest tip temperature, in K); the recovery
// time runs from the joint's start until the tip is back within the band, and is empty when it
// never came back. The verdict judges the joint against the limits; its name() is the stable
// English word files and databases carry ("ok", "slow recovery", "too deep", "incomplete").
#pragma once

#include "model/deviceidentity.h"

#include <QMetaType>
#include <QString>
#include <optional>

namespace tipscope::model {

enum class JointVerdict {
    Ok,
    SlowRecovery,
    TooDeep,
    // Not judged: a gap in the readings, the tool pulled or the heater off during the joint.
    Incomplete
};

[[nodiscard]] QString jointVerdictName(JointVerdict verdict);
[[nodiscard]] std::optional<JointVerdict> jointVerdictFromName(const QString &name);
inline constexpr JointVerdict kJointVerdicts[] = {JointVerdict::Ok, JointVerdict::SlowRecovery,
                                                  JointVerdict::TooDeep, JointVerdict::Incomplete};

struct JointRecord {
    DeviceIdentity device;
    int port = 0;
    QString tool; // the tool's name in the family's tool table ("C245")
    qint64 startMs = 0;
    qint64 endMs = 0;
    int setpoint = 0;  // °C
    int lowestTip = 0; // °C
    int dipDepth = 0;  // K below the setpoint
    std::optional<qint64> recoveryMs;
    qint64 durationMs = 0;
    int powerPeak = 0;        // %
    double powerIntegral = 0; // %·s
    JointVerdict verdict = JointVerdict::Incomplete;

    friend bool operator==(const JointRecord &a, const JointRecord &b);
    friend bool operator!=(const JointRecord &a, const JointRecord &b) { return !(a == b); }
};

} // namespace tipscope::model

Q_DECLARE_METATYPE(tipscope::model::JointRecord)
