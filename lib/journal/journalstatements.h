// Internal: the writer's prepared statements over its one connection. Each call runs inside
// the transaction the writer opened; a device or work context is stored once and then known by
// its id (forgetIds() after a rollback, whose new ids are gone). Every failing call hands back
// the SQLite error, so the writer can tell a full disk from a record the schema refuses.
#pragma once

#include "journalshared.h"

#include <QHash>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QVariantList>
#include <optional>

namespace tipscope::journal {

class JournalStatements {
public:
    explicit JournalStatements(const QSqlDatabase &db);

    [[nodiscard]] bool prepare(QSqlError *error);
    [[nodiscard]] bool exec(const QString &sql, QSqlError *error);
    // The new row's id.
    [[nodiscard]] std::optional<qint64> insert(const PendingJoint &joint, QSqlError *error);
    [[nodiscard]] std::optional<qint64> insert(const PendingEvent &event, QSqlError *error);
    [[nodiscard]] bool markSent(const SentMarks &marks, QSqlError *error);
    // Deletes up to `limit` of the oldest rows before `cutoffMs`; how many went.
    [[nodiscard]] std::optional<int> prune(Table table, qint64 cutoffMs, int limit,
                                           QSqlError *error);
    void forgetIds();

private:
    // A prepared statement and the values to bind to it.
    struct Bound {
        QSqlQuery &query;
        QVariantList values;
    };

    std::optional<qint64> deviceId(const model::DeviceIdentity &device, QSqlError *error);
    std::optional<qint64> contextId(const model::WorkContext &context, QSqlError *error);
    std::optional<qint64> storedId(QHash<QString, qint64> &cache, const QString &key,
                                   const Bound &find, const Bound &insert, QSqlError *error);
    std::optional<qint64> run(QSqlQuery &query, QSqlError *error);

    QSqlDatabase m_db;
    QSqlQuery m_insertJoint;
    QSqlQuery m_insertEvent;
    QSqlQuery m_findDevice;
    QSqlQuery m_insertDevice;
    QSqlQuery m_findContext;
    QSqlQuery m_insertContext;
    QSqlQuery m_markJoint;
    QSqlQuery m_markEvent;
    QSqlQuery m_markEventCfx;
    QSqlQuery m_pruneJoints;
    QSqlQuery m_pruneEvents;
    QHash<QString, qint64> m_deviceIds;  // by DeviceIdentity::key()
    QHash<QString, qint64> m_contextIds; // by the three fields joined with a NUL
};

} // namespace tipscope::journal
