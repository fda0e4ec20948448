// Settings kept in the journal file itself (schema 3), so every TipScope program that opens the
// same journal (the GUI, the CLI, the line service) prunes it alike, whoever set them last.
//
// Today one setting: the retention, in days (0 keeps everything). A journal that was never told
// one keeps records for kDefaultRetentionDays.
#pragma once

#include "base/outcome.h"

#include <QSqlDatabase>

namespace tipscope::journal {

inline constexpr int kDefaultRetentionDays = 365;
// Longer than any plant keeps records; a bound keeps "days × a day in ms" far from overflow.
inline constexpr int kMaxRetentionDays = 36500;

// The stored retention, or kDefaultRetentionDays when none was stored.
[[nodiscard]] base::Outcome<int> readRetentionDays(QSqlDatabase &db);
[[nodiscard]] base::Outcome<void> storeRetentionDays(QSqlDatabase &db, int days);
// Why `days` cannot be a retention, or nothing when it can.
[[nodiscard]] base::Outcome<void> checkRetentionDays(int days);

} // namespace tipscope::journal
