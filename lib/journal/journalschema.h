// The journal's SQLite schema: its version (PRAGMA user_version), the ordered migrations that
// bring any older file to it, and the connection settings every journal connection uses.
//
// Version 1: devices, work contexts, joints and events, with the indexes the time-range queries
// use. Version 2: store-and-forward, a `sent` mark per joint and event and an index of the unsent
// ones. Version 3: settings every program that opens the file shares (the retention). Version 4:
// how sure each joint's figures are. Version 5: a CFX `cfx_sent` mark per event. A new file
// runs every migration in order, so a new file and a migrated one are alike. Migrations run in one
// IMMEDIATE transaction that re-reads the version first, so two programs opening an old file
// together migrate it once. A file written by a newer TipScope (a higher version) or by another
// program (tables but no version, or another application id) is refused and left untouched.
#pragma once

#include "journalstate.h"

#include "base/outcome.h"

#include <QSqlDatabase>
#include <QString>

namespace tipscope::journal {

inline constexpr int kJournalSchemaVersion = 6;
inline constexpr int kJournalApplicationId = 0x54695053; // "TiPS"

// A fresh connection to the file at `path` named `connectionName`, open, in WAL mode with full
// synchronous commits, and migrated. `maxSizeBytes` > 0 caps the file. On failure the
// connection is removed again, the reason is in the user's language and `problem`, when given,
// says its kind.
[[nodiscard]] base::Outcome<void> openJournalDatabase(const QString &path,
                                                      const QString &connectionName,
                                                      qint64 maxSizeBytes,
                                                      JournalProblem *problem = nullptr);
// A connection that only reads (SQLite's read-only open): nothing is configured or migrated,
// so a journal on a read-only mount, or another user's, can be read. A foreign or newer file is
// refused as by openJournalDatabase(); `version` gets the file's schema, which an older file
// must be migrated from before the reader's queries fit it.
[[nodiscard]] base::Outcome<void> openJournalForReading(const QString &path,
                                                        const QString &connectionName,
                                                        qint64 *version,
                                                        JournalProblem *problem = nullptr);
// Brings an open database to kJournalSchemaVersion.
[[nodiscard]] base::Outcome<void> migrateJournal(QSqlDatabase &db);

} // namespace tipscope::journal
