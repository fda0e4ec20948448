// How the journal explains a failed SQLite call to people, and whether the failure is the
// environment's (disk full, read-only, locked, damaged: keep the records and try again later)
// or the record's own (a constraint it breaks: retrying cannot help, so it is counted lost).
#pragma once

#include "journalstate.h"

#include <QSqlError>
#include <QString>

namespace tipscope::journal {

// A sentence naming the journal file and what is wrong, in the user's language.
[[nodiscard]] QString describeSqlError(const QSqlError &error, const QString &path);
[[nodiscard]] bool isRecordError(const QSqlError &error);
// The kind of problem describeSqlError() tells.
[[nodiscard]] JournalProblem problemOf(const QSqlError &error);
[[nodiscard]] QString readOnlyJournalText(const QString &path);

} // namespace tipscope::journal
