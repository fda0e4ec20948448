#include "journalschema.h"

#include "sqlerror.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSqlQuery>
#include <QVariant>
#include <initializer_list>
#include <optional>

namespace tipscope::journal {

using base::failure;
using base::Outcome;

namespace {

struct JournalSchemaTr {
    Q_DECLARE_TR_FUNCTIONS(Journal)
};

struct Migration {
    int version;
    std::initializer_list<const char *> statements;
};

// Never edit a migration that has shipped: add the next one.
const Migration kMigrations[] = {
    {1,
     {"CREATE TABLE devices (id INTEGER PRIMARY KEY, key TEXT NOT NULL UNIQUE, "
      "line TEXT NOT NULL, address INTEGER, model TEXT NOT NULL, software TEXT NOT NULL)",
      "CREATE TABLE contexts (id INTEGER PRIMARY KEY, work_order TEXT NOT NULL, "
      "board_serial TEXT NOT NULL, operator TEXT NOT NULL, "
      "UNIQUE (work_order, board_serial, operator))",
      "CREATE TABLE joints (id INTEGER PRIMARY KEY AUTOINCREMENT, uid BLOB NOT NULL, "
      "context_id INTEGER NOT NULL, device_id INTEGER NOT NULL, port INTEGER NOT NULL, "
      "tool TEXT NOT NULL, start_ms INTEGER NOT NULL, end_ms INTEGER NOT NULL, "
      "setpoint INTEGER NOT NULL, lowest_tip INTEGER NOT NULL, dip_depth INTEGER NOT NULL, "
      "recovery_ms INTEGER, duration_ms INTEGER NOT NULL, power_peak INTEGER NOT NULL, "
      "power_integral REAL NOT NULL, verdict TEXT NOT NULL)",
      "CREATE INDEX joints_by_time ON joints (start_ms)",
      "CREATE INDEX joints_by_port ON joints (port, start_ms)",
      "CREATE INDEX joints_by_device ON joints (device_id, start_ms)",
      "CREATE TABLE events (id INTEGER PRIMARY KEY AUTOINCREMENT, uid BLOB NOT NULL, "
      "context_id INTEGER NOT NULL, device_id INTEGER, port INTEGER, time_ms INTEGER NOT NULL, "
      "kind TEXT NOT NULL, severity TEXT NOT NULL, text TEXT NOT NULL, details TEXT)",
      "CREATE INDEX events_by_time ON events (time_ms)",
      "CREATE INDEX events_by_device ON events (device_id, time_ms)"}},
    {2,
     {"ALTER TABLE joints ADD COLUMN sent INTEGER NOT NULL DEFAULT 0",
      "CREATE INDEX joints_unsent ON joints (id) WHERE sent = 0",
      "ALTER TABLE events ADD COLUMN sent INTEGER NOT NULL DEFAULT 0",
      "CREATE INDEX events_unsent ON events (id) WHERE sent = 0"}},
    {3, {"CREATE TABLE settings (key TEXT PRIMARY KEY, value TEXT NOT NULL)"}},
    // How sure each joint's figures are; lowest_tip and dip_depth hold tenths of a degree from
    // here on (SQLite keeps a fractional value in an INTEGER column as it is).
    {4,
     {"ALTER TABLE joints ADD COLUMN start_uncertainty_ms INTEGER NOT NULL DEFAULT 0",
      "ALTER TABLE joints ADD COLUMN dip_uncertainty_k REAL NOT NULL DEFAULT 0",
      "ALTER TABLE joints ADD COLUMN recovery_uncertainty_ms INTEGER NOT NULL DEFAULT 0",
      "ALTER TABLE joints ADD COLUMN recovery_bounded INTEGER NOT NULL DEFAULT 0"}},
    // IPC-CFX store-and-forward, a mark of its own beside MQTT's, so each broker takes every
    // event once. Events older than the migration are not a CFX endpoint's to send.
    {5,
     {"ALTER TABLE events ADD COLUMN cfx_sent INTEGER NOT NULL DEFAULT 0",
      "UPDATE events SET cfx_sent = 1",
      "CREATE INDEX events_cfx_unsent ON events (id) WHERE cfx_sent = 0"}},
    // The limits each joint was judged by, for the board record and CFX; NULL in older joints,
    // whose limits nobody kept. And indexes for the records of one work context (a board's),
    // which were found by reading every joint and event.
    {6,
     {"ALTER TABLE joints ADD COLUMN band_k INTEGER",
      "ALTER TABLE joints ADD COLUMN max_recovery_ms INTEGER",
      "ALTER TABLE joints ADD COLUMN max_dip_k INTEGER",
      "CREATE INDEX joints_by_context ON joints (context_id, start_ms)",
      "CREATE INDEX events_by_context ON events (context_id, time_ms)"}},
};

// A failure with its kind, so that a front end can tell waiting from a person's work.
struct Failed {
    JournalProblem problem = JournalProblem::Other;
    QString text;
};
template <typename T> using Result = Outcome<T, Failed>;

Failed sqlFailed(const QSqlError &error, const QString &path) {
    return {problemOf(error, path), describeSqlError(error, path)};
}

Result<void> run(QSqlDatabase &db, const QString &sql) {
    QSqlQuery query(db);
    if (query.exec(sql))
        return {};
    return failure(sqlFailed(query.lastError(), db.databaseName()));
}

// The integer a pragma or a one-value query answers, or why the query failed.
Result<qint64> readInteger(QSqlDatabase &db, const QString &sql) {
    QSqlQuery query(db);
    if (query.exec(sql) && query.next())
        return query.value(0).toLongLong();
    return failure(sqlFailed(query.lastError(), db.databaseName()));
}

// The file's schema version, if the file is ours to migrate: not another program's database,
// not a newer journal. Reads only, so a refused file is left as it was.
Result<qint64> ownedVersion(QSqlDatabase &db) {
    const QString path = db.databaseName();
    const auto version = readInteger(db, QStringLiteral("PRAGMA user_version"));
    if (!version)
        return version;
    if (*version > kJournalSchemaVersion)
        return failure(Failed{
            JournalProblem::Newer,
            JournalSchemaTr::tr("The journal %1 was written by a newer TipScope (schema %2; this "
                                "one knows up to %3). It was left untouched.")
                .arg(path)
                .arg(*version)
                .arg(kJournalSchemaVersion)});
    const auto applicationId = readInteger(db, QStringLiteral("PRAGMA application_id"));
    if (!applicationId)
        return applicationId;
    const auto tables = readInteger(db, QStringLiteral("SELECT count(*) FROM sqlite_master"));
    if (!tables)
        return tables;
    const bool foreignId = *applicationId != 0 && *applicationId != kJournalApplicationId;
    if (foreignId || (*version == 0 && *tables > 0))
        return failure(Failed{
            JournalProblem::Foreign,
            JournalSchemaTr::tr("The file %1 is not a TipScope journal. It was left untouched.")
                .arg(path)});
    return version;
}

Result<void> runMigrations(QSqlDatabase &db, qint64 from) {
    for (const Migration &migration : kMigrations) {
        if (migration.version <= from)
            continue;
        for (const char *statement : migration.statements)
            if (const auto ran = run(db, QString::fromLatin1(statement)); !ran)
                return ran;
    }
    if (const auto ran =
            run(db, QStringLiteral("PRAGMA application_id = %1").arg(kJournalApplicationId));
        !ran)
        return ran;
    return run(db, QStringLiteral("PRAGMA user_version = %1").arg(kJournalSchemaVersion));
}

Result<void> configure(QSqlDatabase &db, qint64 maxSizeBytes) {
    QSqlQuery mode(db);
    if (!mode.exec(QStringLiteral("PRAGMA journal_mode = WAL")) || !mode.next())
        return failure(sqlFailed(mode.lastError(), db.databaseName()));
    if (mode.value(0).toString().compare(QLatin1String("wal"), Qt::CaseInsensitive) != 0)
        return failure(Failed{JournalProblem::ReadOnly, readOnlyJournalText(db.databaseName())});
    // FULL: a commit is on the disk, not only in the system's cache, when durable() is said.
    if (const auto ran = run(db, QStringLiteral("PRAGMA synchronous = FULL")); !ran)
        return ran;
    if (maxSizeBytes <= 0)
        return {};
    const auto pageSize = readInteger(db, QStringLiteral("PRAGMA page_size"));
    if (!pageSize)
        return failure(pageSize.error());
    const auto capped = readInteger(db, QStringLiteral("PRAGMA max_page_count = %1")
                                            .arg(qMax<qint64>(1, maxSizeBytes / *pageSize)));
    if (!capped)
        return failure(capped.error());
    return {};
}

Result<void> migrate(QSqlDatabase &db) {
    const auto version = ownedVersion(db);
    if (!version)
        return failure(version.error());
    if (*version == kJournalSchemaVersion)
        return {};
    if (const auto ran = run(db, QStringLiteral("BEGIN IMMEDIATE")); !ran)
        return ran;
    // Another program may have migrated the file while this one waited for the lock.
    const auto done = [&db]() -> Result<void> {
        const auto locked = ownedVersion(db);
        if (!locked)
            return failure(locked.error());
        if (const auto migrated = runMigrations(db, *locked); !migrated)
            return migrated;
        return run(db, QStringLiteral("COMMIT"));
    }();
    if (!done)
        QSqlQuery(db).exec(QStringLiteral("ROLLBACK"));
    return done;
}

// Checks the file is ours, sets the connection up and migrates it.
Result<void> prepare(QSqlDatabase &db, qint64 maxSizeBytes) {
    if (const auto owned = ownedVersion(db); !owned)
        return failure(owned.error());
    if (const auto configured = configure(db, maxSizeBytes); !configured)
        return configured;
    return migrate(db);
}

} // namespace

Outcome<void> migrateJournal(QSqlDatabase &db) {
    if (const auto migrated = migrate(db); !migrated)
        return failure(migrated.error().text);
    return {};
}

Outcome<void> openJournalForReading(const QString &path, const QString &connectionName,
                                    qint64 *version, JournalProblem *problem) {
    Result<qint64> owned = qint64(0);
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connectionName);
        db.setDatabaseName(path);
        db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY;QSQLITE_BUSY_TIMEOUT=5000"));
        owned =
            db.open() ? ownedVersion(db) : Result<qint64>(failure(sqlFailed(db.lastError(), path)));
        if (!owned)
            db.close();
    }
    if (problem)
        *problem = owned ? JournalProblem::None : owned.error().problem;
    if (owned) {
        *version = *owned;
        return {};
    }
    QSqlDatabase::removeDatabase(connectionName);
    return failure(owned.error().text);
}

Outcome<void> openJournalDatabase(const QString &path, const QString &connectionName,
                                  qint64 maxSizeBytes, JournalProblem *problem) {
    const QString folder = QFileInfo(path).absolutePath();
    Result<void> opened;
    if (!QDir().mkpath(folder)) {
        opened = failure(Failed{
            JournalProblem::ReadOnly,
            JournalSchemaTr::tr("Cannot create the folder %1 for the journal.").arg(folder)});
    } else {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connectionName);
        db.setDatabaseName(path);
        db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=5000"));
        opened = db.open() ? prepare(db, maxSizeBytes)
                           : Result<void>(failure(sqlFailed(db.lastError(), path)));
        if (!opened)
            db.close();
    }
    if (problem)
        *problem = opened ? JournalProblem::None : opened.error().problem;
    if (opened)
        return {};
    if (QSqlDatabase::contains(connectionName))
        QSqlDatabase::removeDatabase(connectionName);
    return failure(opened.error().text);
}

} // namespace tipscope::journal
