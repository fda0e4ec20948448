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
// The kind of problem describeSqlError() tells. An I/O error on a disk with next to no room, or
// on a journal at the process's file size limit, is told as full: waiting for space is the cure.
[[nodiscard]] JournalProblem problemOf(const QSqlError &error, const QString &path);
[[nodiscard]] QString readOnlyJournalText(const QString &path);

} // namespace tipscope::journal
