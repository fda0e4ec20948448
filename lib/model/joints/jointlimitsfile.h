// The joint limits people set, kept in one JSON file that the GUI's preferences and
// `tipscope-cli limits` both edit and every program reads (JointLimitRules::toJson()'s form):
// ~/.config/TipScope/joint-limits.json. A missing file means the default limits.
#pragma once

#include "model/joints/jointlimitrules.h"

namespace tipscope::model {

[[nodiscard]] QString defaultJointLimitsPath();
[[nodiscard]] base::Outcome<JointLimitRules> loadJointLimits(const QString &path);
[[nodiscard]] base::Outcome<void> saveJointLimits(const QString &path,
                                                  const JointLimitRules &rules);

} // namespace tipscope::model
