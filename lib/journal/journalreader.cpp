#include "journalreader.h"

#include "journalschema.h"
#include "journalselect.h"
#include "sqlerror.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QHash>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <algorithm>
#include <cmath>

namespace tipscope::journal {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(Journal)
};

// Runs `select` forward-only; each row goes to `row`.
template <typename Row>
bool run(const QString &connection, const Select &select, QString *error, Row row) {
    QSqlDatabase db = QSqlDatabase::database(connection, false);
    if (!db.isOpen()) {
        *error = Tr::tr("No journal is open.");
        return false;
    }
    QSqlQuery query(db);
    query.setForwardOnly(true);
    if (!query.prepare(select.sql)) {
        *error = describeSqlError(query.lastError(), db.databaseName());
        return false;
    }
    for (int i = 0; i < select.values.size(); ++i)
        query.bindValue(i, select.values.at(i));
    if (!query.exec()) {
        *error = describeSqlError(query.lastError(), db.databaseName());
        return false;
    }
    while (query.next())
        row(query);
    return true;
}

template <typename T, typename Read>
std::optional<QList<T>> collect(const QString &connection, const Select &select, QString *error,
                                Read read) {
    QList<T> out;
    if (!run(connection, select, error, [&](const QSqlQuery &q) { out.append(read(q)); }))
        return std::nullopt;
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

bool JournalReader::open(const QString &path, QString *error) {
    close();
    m_path = path;
    if (!QFileInfo(path).isFile()) {
        *error = Tr::tr("There is no journal at %1.").arg(path);
        return false;
    }
    if (!openJournalDatabase(path, m_connection, 0, error))
        return false;
    m_open = true;
    // The reader never writes, whatever a caller's SQL might try.
    return run(m_connection, {QStringLiteral("PRAGMA query_only = 1"), {}}, error,
               [](const QSqlQuery &) {});
}

std::optional<QList<StoredJoint>> JournalReader::joints(const JointFilter &filter,
                                                        QString *error) const {
    return collect<StoredJoint>(m_connection, selectJoints(filter), error, readJoint);
}

std::optional<QList<StoredEvent>> JournalReader::events(const EventFilter &filter,
                                                        QString *error) const {
    return collect<StoredEvent>(m_connection, selectEvents(filter), error, readEvent);
}

std::optional<qint64> JournalReader::countJoints(const JointFilter &filter, QString *error) const {
    Select select = jointsWhere(filter);
    select.sql.prepend(QStringLiteral("SELECT count(*)"));
    qint64 count = 0;
    if (!run(m_connection, select, error,
             [&](const QSqlQuery &q) { count = q.value(0).toLongLong(); }))
        return std::nullopt;
    return count;
}

std::optional<QMap<model::JointVerdict, qint64>>
JournalReader::verdictCounts(const JointFilter &filter, QString *error) const {
    Select select = jointsWhere(filter);
    select.sql.prepend(QStringLiteral("SELECT j.verdict, count(*)"));
    select.sql.append(QStringLiteral(" GROUP BY j.verdict"));
    QMap<model::JointVerdict, qint64> counts;
    for (const model::JointVerdict verdict : model::kJointVerdicts)
        counts.insert(verdict, 0);
    const bool ok = run(m_connection, select, error, [&](const QSqlQuery &q) {
        if (const auto verdict = model::jointVerdictFromName(q.value(0).toString()))
            counts[*verdict] += q.value(1).toLongLong();
    });
    return ok ? std::optional(counts) : std::nullopt;
}

std::optional<QList<PortRecovery>> JournalReader::recoveryByPort(const JointFilter &filter,
                                                                 QString *error) const {
    QHash<qint64, model::DeviceIdentity> devices;
    const Select allDevices{
        QStringLiteral("SELECT line, address, model, software, id FROM devices"), {}};
    if (!run(m_connection, allDevices, error, [&](const QSqlQuery &q) {
            devices.insert(q.value(4).toLongLong(), readDevice(q, 0));
        }))
        return std::nullopt;
    Select select = jointsWhere(filter);
    select.sql.prepend(QStringLiteral("SELECT j.device_id, j.port, j.recovery_ms"));
    // By device key and port, each with its joints' recovery times.
    QMap<QPair<QString, int>, QPair<qint64, QList<qint64>>> ports;
    const bool ok = run(m_connection, select, error, [&](const QSqlQuery &q) {
        auto &port = ports[{devices.value(q.value(0).toLongLong()).key(), q.value(1).toInt()}];
        ++port.first;
        if (!q.value(2).isNull())
            port.second.append(q.value(2).toLongLong());
    });
    if (!ok)
        return std::nullopt;
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

std::optional<QList<StoredJoint>> JournalReader::unsentJoints(qint64 afterId, int limit,
                                                              QString *error) const {
    return collect<StoredJoint>(m_connection, selectUnsentJoints(afterId, limit), error, readJoint);
}

std::optional<QList<StoredEvent>> JournalReader::unsentEvents(qint64 afterId, int limit,
                                                              QString *error) const {
    return collect<StoredEvent>(m_connection, selectUnsentEvents(afterId, limit), error, readEvent);
}

std::optional<QList<model::DeviceIdentity>> JournalReader::devices(QString *error) const {
    const Select select{
        QStringLiteral("SELECT line, address, model, software FROM devices ORDER BY key"), {}};
    return collect<model::DeviceIdentity>(m_connection, select, error,
                                          [](const QSqlQuery &q) { return readDevice(q, 0); });
}

} // namespace tipscope::journal
