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

namespace {

struct Tr {
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
};

bool run(QSqlDatabase &db, const QString &sql, QString *error) {
    QSqlQuery query(db);
    if (query.exec(sql))
        return true;
    *error = describeSqlError(query.lastError(), db.databaseName());
    return false;
}

// The integer a pragma or a one-value query answers; nullopt (and `error`) when it fails.
std::optional<qint64> readInteger(QSqlDatabase &db, const QString &sql, QString *error) {
    QSqlQuery query(db);
    if (query.exec(sql) && query.next())
        return query.value(0).toLongLong();
    *error = describeSqlError(query.lastError(), db.databaseName());
    return std::nullopt;
}

// The file's schema version, if the file is ours to migrate: not another program's database,
// not a newer journal. Reads only, so a refused file is left as it was.
std::optional<qint64> ownedVersion(QSqlDatabase &db, QString *error) {
    const QString path = db.databaseName();
    const std::optional<qint64> version =
        readInteger(db, QStringLiteral("PRAGMA user_version"), error);
    if (!version)
        return std::nullopt;
    if (*version > kJournalSchemaVersion) {
        *error = Tr::tr("The journal %1 was written by a newer TipScope (schema %2; this one knows "
                        "up to %3). It was left untouched.")
                     .arg(path)
                     .arg(*version)
                     .arg(kJournalSchemaVersion);
        return std::nullopt;
    }
    const std::optional<qint64> applicationId =
        readInteger(db, QStringLiteral("PRAGMA application_id"), error);
    const std::optional<qint64> tables =
        readInteger(db, QStringLiteral("SELECT count(*) FROM sqlite_master"), error);
    if (!applicationId || !tables)
        return std::nullopt;
    const bool foreignId = *applicationId != 0 && *applicationId != kJournalApplicationId;
    if (foreignId || (*version == 0 && *tables > 0)) {
        *error = Tr::tr("The file %1 is not a TipScope journal. It was left untouched.").arg(path);
        return std::nullopt;
    }
    return version;
}

bool runMigrations(QSqlDatabase &db, qint64 from, QString *error) {
    for (const Migration &migration : kMigrations) {
        if (migration.version <= from)
            continue;
        for (const char *statement : migration.statements) {
            if (!run(db, QString::fromLatin1(statement), error))
                return false;
        }
    }
    return run(db, QStringLiteral("PRAGMA application_id = %1").arg(kJournalApplicationId),
               error) &&
           run(db, QStringLiteral("PRAGMA user_version = %1").arg(kJournalSchemaVersion), error);
}

bool configure(QSqlDatabase &db, qint64 maxSizeBytes, QString *error) {
    QSqlQuery mode(db);
    if (!mode.exec(QStringLiteral("PRAGMA journal_mode = WAL")) || !mode.next()) {
        *error = describeSqlError(mode.lastError(), db.databaseName());
        return false;
    }
    if (mode.value(0).toString().compare(QLatin1String("wal"), Qt::CaseInsensitive) != 0) {
        *error = readOnlyJournalText(db.databaseName());
        return false;
    }
    // FULL: a commit is on the disk, not only in the system's cache, when durable() is said.
    if (!run(db, QStringLiteral("PRAGMA synchronous = FULL"), error))
        return false;
    if (maxSizeBytes <= 0)
        return true;
    const std::optional<qint64> pageSize =
        readInteger(db, QStringLiteral("PRAGMA page_size"), error);
    return pageSize && readInteger(db,
                                   QStringLiteral("PRAGMA max_page_count = %1")
                                       .arg(qMax<qint64>(1, maxSizeBytes / *pageSize)),
                                   error);
}

} // namespace

bool migrateJournal(QSqlDatabase &db, QString *error) {
    const std::optional<qint64> version = ownedVersion(db, error);
    if (!version)
        return false;
    if (*version == kJournalSchemaVersion)
        return true;
    if (!run(db, QStringLiteral("BEGIN IMMEDIATE"), error))
        return false;
    // Another program may have migrated the file while this one waited for the lock.
    const std::optional<qint64> locked = ownedVersion(db, error);
    const bool done =
        locked && runMigrations(db, *locked, error) && run(db, QStringLiteral("COMMIT"), error);
    if (!done)
        QSqlQuery(db).exec(QStringLiteral("ROLLBACK"));
    return done;
}

bool openJournalDatabase(const QString &path, const QString &connectionName, qint64 maxSizeBytes,
                         QString *error) {
    const QString folder = QFileInfo(path).absolutePath();
    if (!QDir().mkpath(folder)) {
        *error = Tr::tr("Cannot create the folder %1 for the journal.").arg(folder);
        return false;
    }
    bool ok = false;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connectionName);
        db.setDatabaseName(path);
        db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=5000"));
        if (!db.open())
            *error = describeSqlError(db.lastError(), path);
        else
            ok = ownedVersion(db, error) && configure(db, maxSizeBytes, error) &&
                 migrateJournal(db, error);
        if (!ok)
            db.close();
    }
    if (!ok)
        QSqlDatabase::removeDatabase(connectionName);
    return ok;
}

} // namespace tipscope::journal
