#include "journalreader.h"

#include "journalschema.h"
#include "journalselect.h"
#include "journalsettings.h"
#include "sqlerror.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QHash>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <algorithm>
#include <cmath>

namespace tipscope::journal {

using base::failure;
using base::Outcome;

namespace {

struct JournalReaderTr {
    Q_DECLARE_TR_FUNCTIONS(Journal)
};

// Runs `select` forward-only; each row goes to `row`.
template <typename Row>
Outcome<void> run(const QString &connection, const Select &select, Row row) {
    QSqlDatabase db = QSqlDatabase::database(connection, false);
    if (!db.isOpen())
        return failure(JournalReaderTr::tr("No journal is open."));
    QSqlQuery query(db);
    query.setForwardOnly(true);
    if (!query.prepare(select.sql))
        return failure(describeSqlError(query.lastError(), db.databaseName()));
    for (int i = 0; i < select.values.size(); ++i)
        query.bindValue(i, select.values.at(i));
    if (!query.exec())
        return failure(describeSqlError(query.lastError(), db.databaseName()));
    while (query.next())
        row(query);
    return {};
}

template <typename T, typename Read>
Outcome<QList<T>> collect(const QString &connection, const Select &select, Read read) {
    QList<T> out;
    if (const auto ran = run(connection, select, [&](const QSqlQuery &q) { out.append(read(q)); });
        !ran)
        return failure(ran.error());
    return out;
}

// Nearest rank, as tipscope-bench and the support report compute quantiles.
qint64 quantile(const QList<qint64> &sorted, double p) {
    if (sorted.isEmpty())
        return 0;
    const auto rank = qsizetype(std::ceil(p * double(sorted.size())));
    return sorted.at(std::clamp<qsizetype>(rank - 1, 0, sorted.size() - 1));
}

} // namespace

JournalReader::JournalReader()
    : m_connection(QStringLiteral("tipscope.journal.reader.%1").arg(quintptr(this), 0, 16)) {}

JournalReader::~JournalReader() {
    close();
}

void JournalReader::close() {
    if (!m_open)
        return;
    QSqlDatabase::database(m_connection, false).close();
    QSqlDatabase::removeDatabase(m_connection);
    m_open = false;
}

Outcome<void> JournalReader::keepOpen(const QString &path) {
    if (m_open)
        return {};
    return open(path);
}

Outcome<void> JournalReader::open(const QString &path) {
    close();
    m_path = path;
    m_problem = JournalProblem::Missing;
    if (!QFileInfo(path).isFile())
        return failure(JournalReaderTr::tr("There is no journal at %1.").arg(path));
    qint64 version = 0;
    if (const auto opened = openJournalForReading(path, m_connection, &version, &m_problem);
        !opened)
        return opened;
    // An older file is migrated as the writer would, which needs write access once; a current
    // one is only read, so a read-only mount or another user's journal opens.
    if (version < kJournalSchemaVersion) {
        QSqlDatabase::database(m_connection, false).close();
        QSqlDatabase::removeDatabase(m_connection);
        if (const auto opened = openJournalDatabase(path, m_connection, 0, &m_problem); !opened)
            return opened;
    }
    m_open = true;
    // The reader never writes, whatever a caller's SQL might try.
    return run(m_connection, {QStringLiteral("PRAGMA query_only = 1"), {}},
               [](const QSqlQuery &) {});
}

Outcome<void> JournalReader::check() {
    QStringList findings;
    const auto ran =
        run(m_connection, {QStringLiteral("PRAGMA quick_check"), {}},
            [&findings](const QSqlQuery &q) { findings.append(q.value(0).toString()); });
    if (!ran) {
        m_problem = JournalProblem::Damaged;
        return ran;
    }
    if (findings == QStringList{QStringLiteral("ok")})
        return {};
    m_problem = JournalProblem::Damaged;
    return failure(JournalReaderTr::tr("The journal %1 is damaged (%n finding(s), the first: %2).",
                                       nullptr, int(findings.size()))
                       .arg(m_path, findings.value(0)));
}

Outcome<QList<StoredJoint>> JournalReader::joints(const JointFilter &filter) const {
    return collect<StoredJoint>(m_connection, selectJoints(filter), readJoint);
}

Outcome<QList<StoredEvent>> JournalReader::events(const EventFilter &filter) const {
    return collect<StoredEvent>(m_connection, selectEvents(filter), readEvent);
}

Outcome<qint64> JournalReader::countJoints(const JointFilter &filter) const {
    Select select = jointsWhere(filter);
    select.sql.prepend(QStringLiteral("SELECT count(*)"));
    qint64 count = 0;
    if (const auto ran =
            run(m_connection, select, [&](const QSqlQuery &q) { count = q.value(0).toLongLong(); });
        !ran)
        return failure(ran.error());
    return count;
}

Outcome<QMap<model::JointVerdict, qint64>>
JournalReader::verdictCounts(const JointFilter &filter) const {
    Select select = jointsWhere(filter);
    select.sql.prepend(QStringLiteral("SELECT j.verdict, count(*)"));
    select.sql.append(QStringLiteral(" GROUP BY j.verdict"));
    QMap<model::JointVerdict, qint64> counts;
    for (const model::JointVerdict verdict : model::kJointVerdicts)
        counts.insert(verdict, 0);
    const auto ran = run(m_connection, select, [&](const QSqlQuery &q) {
        if (const auto verdict = model::jointVerdictFromName(q.value(0).toString()))
            counts[*verdict] += q.value(1).toLongLong();
    });
    if (!ran)
        return failure(ran.error());
    return counts;
}

Outcome<QList<PortRecovery>> JournalReader::recoveryByPort(const JointFilter &filter) const {
    QHash<qint64, model::DeviceIdentity> devices;
    const Select allDevices{
        QStringLiteral("SELECT line, address, model, software, id FROM devices"), {}};
    if (const auto ran = run(
            m_connection, allDevices,
            [&](const QSqlQuery &q) { devices.insert(q.value(4).toLongLong(), readDevice(q, 0)); });
        !ran)
        return failure(ran.error());
    Select select = jointsWhere(filter);
    select.sql.prepend(QStringLiteral("SELECT j.device_id, j.port, j.recovery_ms"));
    // By device key and port, each with its joints' recovery times.
    QMap<QPair<QString, int>, QPair<qint64, QList<qint64>>> ports;
    const auto ran = run(m_connection, select, [&](const QSqlQuery &q) {
        auto &port = ports[{devices.value(q.value(0).toLongLong()).key(), q.value(1).toInt()}];
        ++port.first;
        if (!q.value(2).isNull())
            port.second.append(q.value(2).toLongLong());
    });
    if (!ran)
        return failure(ran.error());
    QList<PortRecovery> out;
    for (auto it = ports.begin(); it != ports.end(); ++it) {
        QList<qint64> &times = it.value().second;
        std::sort(times.begin(), times.end());
        out.append(
            {model::DeviceIdentity::fromKey(it.key().first).value_or(model::DeviceIdentity()),
             it.key().second, it.value().first, times.size(), quantile(times, 0.5),
             quantile(times, 0.95)});
    }
    return out;
}

Outcome<QList<StoredJoint>> JournalReader::unsentJoints(qint64 afterId, int limit) const {
    return collect<StoredJoint>(m_connection, selectUnsentJoints(afterId, limit), readJoint);
}

Outcome<QList<StoredEvent>> JournalReader::unsentEvents(qint64 afterId, int limit,
                                                        SentChannel channel) const {
    return collect<StoredEvent>(m_connection, selectUnsentEvents(afterId, limit, channel),
                                readEvent);
}

Outcome<QList<model::DeviceIdentity>> JournalReader::devices() const {
    const Select select{
        QStringLiteral("SELECT line, address, model, software FROM devices ORDER BY key"), {}};
    return collect<model::DeviceIdentity>(m_connection, select,
                                          [](const QSqlQuery &q) { return readDevice(q, 0); });
}

Outcome<JournalSummary> JournalReader::summary() const {
    const Select select{
        QStringLiteral("SELECT (SELECT count(*) FROM joints), (SELECT count(*) FROM events), "
                       "(SELECT count(*) FROM joints WHERE sent = 0), "
                       "(SELECT count(*) FROM events WHERE sent = 0), "
                       "(SELECT min(t) FROM (SELECT min(start_ms) AS t FROM joints "
                       "UNION ALL SELECT min(time_ms) FROM events)), "
                       "(SELECT max(t) FROM (SELECT max(end_ms) AS t FROM joints "
                       "UNION ALL SELECT max(time_ms) FROM events))"),
        {}};
    JournalSummary out;
    const auto optionalTime = [](const QVariant &v) {
        return v.isNull() ? std::nullopt : std::optional<qint64>(v.toLongLong());
    };
    if (const auto ran = run(m_connection, select,
                             [&](const QSqlQuery &q) {
                                 out.joints = q.value(0).toLongLong();
                                 out.events = q.value(1).toLongLong();
                                 out.unsentJoints = q.value(2).toLongLong();
                                 out.unsentEvents = q.value(3).toLongLong();
                                 out.oldestMs = optionalTime(q.value(4));
                                 out.newestMs = optionalTime(q.value(5));
                             });
        !ran)
        return failure(ran.error());
    const auto days = retentionDays();
    if (!days)
        return failure(days.error());
    out.retentionDays = *days;
    out.fileBytes = QFileInfo(m_path).size() + QFileInfo(m_path + QStringLiteral("-wal")).size();
    return out;
}

Outcome<int> JournalReader::retentionDays() const {
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    if (!db.isOpen())
        return failure(JournalReaderTr::tr("No journal is open."));
    return readRetentionDays(db);
}

} // namespace tipscope::journal
