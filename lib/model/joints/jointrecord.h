// JointRecord: one solder joint as the joint detector measured and judged it. A plain value.
//
// Units are the wire's: times in milliseconds since the epoch (UTC), temperatures in °C, power
// in %, durations in milliseconds, the power-time integral in %·s. The dip depth is how far the
// tip fell below the setpoint (setpoint minus the lowest tip temperature, in K, to a tenth: it
// is estimated from the readings around the lowest, finer than the station's whole degrees);
// the recovery time runs from the joint's start until the tip is back within the band, and is
// empty when it never came back. The verdict judges the joint against the limits; its name() is
// the stable English word files and databases carry ("ok", "slow recovery", "too deep",
// "incomplete").
//
// Each figure says how sure it is: the true value lies within ± its uncertainty, as far as the
// readings around it tell (docs/joints.md). A recovery the readings could only bound (they were
// too far apart, or a gap came first) is `recoveryBounded`: it lies somewhere in recoveryMs ±
// recoveryUncertaintyMs, and it is never judged ok unless the whole of that interval is.
#pragma once

#include "model/context/deviceidentity.h"

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

// The limits a joint's verdict was judged by (JointLimits without what judges a tip, not a joint).
struct JudgedLimits {
    int bandK = 0;
    qint64 maxRecoveryMs = 0;
    int maxDipK = 0;

    friend bool operator==(const JudgedLimits &a, const JudgedLimits &b) {
        return a.bandK == b.bandK && a.maxRecoveryMs == b.maxRecoveryMs && a.maxDipK == b.maxDipK;
    }
};

struct JointRecord {
    DeviceIdentity device;
    int port = 0;
    QString tool; // the tool's name in the family's tool table ("C245")
    qint64 startMs = 0;
    qint64 endMs = 0;
    int setpoint = 0;     // °C
    double lowestTip = 0; // °C
    double dipDepth = 0;  // K below the setpoint
    std::optional<qint64> recoveryMs;
    qint64 durationMs = 0;
    int powerPeak = 0;        // %
    double powerIntegral = 0; // %·s
    JointVerdict verdict = JointVerdict::Incomplete;
    qint64 startUncertaintyMs = 0;
    double dipUncertaintyK = 0;
    qint64 recoveryUncertaintyMs = 0;
    bool recoveryBounded = false;
    // Empty for a joint journaled before the limits were kept with it (journal schema 6).
    std::optional<JudgedLimits> limits;

    friend bool operator==(const JointRecord &a, const JointRecord &b);
    friend bool operator!=(const JointRecord &a, const JointRecord &b) { return !(a == b); }
};

// The recovery as the command line prints it, in the same words in every language: "1.84 s",
// "2.0-3.0 s bounded" for one known only between two readings, "-" for none.
[[nodiscard]] QString recoveryWords(const JointRecord &joint);

} // namespace tipscope::model

Q_DECLARE_METATYPE(tipscope::model::JointRecord)
