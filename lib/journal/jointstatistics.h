// Joint statistics for the support report: per device and port over a time range, the joints
// counted by verdict and the median and 95th percentile of their recovery times, read from the
// journal. The report carries them under "joints" (JSON) and as a section of its text:
//     {"since": "...", "until": "...", "ports": [{"device": "DME-2C at 01 on demo, software …",
//       "deviceKey": "...", "port": 1, "joints": 240, "ok": 236, "slow recovery": 3,
//       "too deep": 0, "incomplete": 1, "recoveryMedianMs": 1620, "recoveryP95Ms": 1880}]}
// A journal that cannot be read gives {"error": "why"} instead, so the report is still written.
#pragma once

#include "journalreader.h"

#include <QJsonObject>

namespace tipscope::journal {

[[nodiscard]] base::Outcome<QJsonObject> jointStatistics(const JournalReader &reader,
                                                         qint64 sinceMs, qint64 untilMs);
// The last 24 hours of the journal at `path`, for the report.
[[nodiscard]] QJsonObject lastDayOfJoints(const QString &path);

} // namespace tipscope::journal
