// The journal's health for the support report, under "journal": where it is, whether it writes
// (and why not), what it lost, what waits in memory, and what the file holds:
//     {"path": "...", "state": "ready", "error": "", "lost": 0, "lossReason": "",
//      "pending": 0, "joints": 9120, "events": 311, "unsentJoints": 0, "unsentEvents": 0,
//      "oldest": "2026-...Z", "newest": "2026-...Z", "retentionDays": 365, "bytes": 1503232}
// When the file cannot be read, "readError" says why and the rest of the file's part is left
// out; the report is written all the same.
#pragma once

#include "journal.h"

#include <QJsonObject>

namespace tipscope::journal {

[[nodiscard]] QJsonObject journalHealth(const Journal &journal);

} // namespace tipscope::journal
