#include "journalstatements.h"

#include <QJsonDocument>
#include <QVariant>

namespace tipscope::journal {

namespace {

const char kInsertJoint[] =
    "INSERT INTO joints (uid, context_id, device_id, port, tool, start_ms, end_ms, setpoint, "
    "lowest_tip, dip_depth, recovery_ms, duration_ms, power_peak, power_integral, verdict, "
    "start_uncertainty_ms, dip_uncertainty_k, recovery_uncertainty_ms, recovery_bounded, band_k, "
    "max_recovery_ms, max_dip_k) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
    "?, ?, ?)";
const char kInsertEvent[] =
    "INSERT INTO events (uid, context_id, device_id, port, time_ms, kind, severity, text, "
    "details) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)";
const char kFindDevice[] = "SELECT id FROM devices WHERE key = ?";
const char kInsertDevice[] =
    "INSERT INTO devices (key, line, address, model, software) VALUES (?, ?, ?, ?, ?)";
const char kFindContext[] =
    "SELECT id FROM contexts WHERE work_order = ? AND board_serial = ? AND operator = ?";
const char kInsertContext[] =
    "INSERT INTO contexts (work_order, board_serial, operator) VALUES (?, ?, ?)";
const char kMarkJoint[] = "UPDATE joints SET sent = 1 WHERE id = ?";
const char kMarkEvent[] = "UPDATE events SET sent = 1 WHERE id = ?";
const char kMarkEventCfx[] = "UPDATE events SET cfx_sent = 1 WHERE id = ?";
const char kPruneJoints[] = "DELETE FROM joints WHERE id IN (SELECT id FROM joints WHERE "
                            "start_ms < ? ORDER BY start_ms LIMIT ?)";
const char kPruneEvents[] = "DELETE FROM events WHERE id IN (SELECT id FROM events WHERE "
                            "time_ms < ? ORDER BY time_ms LIMIT ?)";

QVariant optionalValue(const std::optional<qint64> &value) {
    return value ? QVariant(*value) : QVariant(QMetaType(QMetaType::LongLong));
}

QVariant optionalValue(const std::optional<int> &value) {
    return value ? QVariant(*value) : QVariant(QMetaType(QMetaType::Int));
}

// Qt binds a null QString as SQL NULL; the text columns hold "" for nothing said.
QString text(const QString &value) {
    return value.isNull() ? QStringLiteral("") : value;
}

QString contextKey(const model::WorkContext &context) {
    return context.workOrder + QChar(0) + context.boardSerial + QChar(0) + context.operatorName;
}

} // namespace

JournalStatements::JournalStatements(const QSqlDatabase &db)
    : m_db(db)
    , m_insertJoint(db)
    , m_insertEvent(db)
    , m_findDevice(db)
    , m_insertDevice(db)
    , m_findContext(db)
    , m_insertContext(db)
    , m_markJoint(db)
    , m_markEvent(db)
    , m_markEventCfx(db)
    , m_pruneJoints(db)
    , m_pruneEvents(db) {}

bool JournalStatements::prepare(QSqlError *error) {
    const std::pair<QSqlQuery *, const char *> statements[] = {
        {&m_insertJoint, kInsertJoint},   {&m_insertEvent, kInsertEvent},
        {&m_findDevice, kFindDevice},     {&m_insertDevice, kInsertDevice},
        {&m_findContext, kFindContext},   {&m_insertContext, kInsertContext},
        {&m_markJoint, kMarkJoint},       {&m_markEvent, kMarkEvent},
        {&m_markEventCfx, kMarkEventCfx}, {&m_pruneJoints, kPruneJoints},
        {&m_pruneEvents, kPruneEvents}};
    for (const auto &[query, sql] : statements) {
        if (!query->prepare(QString::fromLatin1(sql))) {
            *error = query->lastError();
            return false;
        }
    }
    return true;
}

bool JournalStatements::exec(const QString &sql, QSqlError *error) {
    QSqlQuery query(m_db);
    if (query.exec(sql))
        return true;
    *error = query.lastError();
    return false;
}

// Executes a prepared statement; the row id it inserted (or 0), nullopt on failure.
std::optional<qint64> JournalStatements::run(QSqlQuery &query, QSqlError *error) {
    if (!query.exec()) {
        *error = query.lastError();
        return std::nullopt;
    }
    const qint64 id = query.lastInsertId().toLongLong();
    query.finish();
    return id;
}

std::optional<qint64> JournalStatements::insert(const PendingJoint &pending, QSqlError *error) {
    const std::optional<qint64> context = contextId(pending.context, error);
    const std::optional<qint64> device =
        context ? deviceId(pending.joint.device, error) : std::nullopt;
    if (!device)
        return std::nullopt;
    const model::JointRecord &j = pending.joint;
    const QVariant values[] = {pending.uid.toRfc4122(),
                               *context,
                               *device,
                               j.port,
                               text(j.tool),
                               j.startMs,
                               j.endMs,
                               j.setpoint,
                               j.lowestTip,
                               j.dipDepth,
                               optionalValue(j.recoveryMs),
                               j.durationMs,
                               j.powerPeak,
                               j.powerIntegral,
                               model::jointVerdictName(j.verdict),
                               j.startUncertaintyMs,
                               j.dipUncertaintyK,
                               j.recoveryUncertaintyMs,
                               j.recoveryBounded ? 1 : 0,
                               j.limits ? QVariant(j.limits->bandK) : QVariant(),
                               j.limits ? QVariant(j.limits->maxRecoveryMs) : QVariant(),
                               j.limits ? QVariant(j.limits->maxDipK) : QVariant()};
    for (int i = 0; i < int(std::size(values)); ++i)
        m_insertJoint.bindValue(i, values[i]);
    return run(m_insertJoint, error);
}

std::optional<qint64> JournalStatements::insert(const PendingEvent &pending, QSqlError *error) {
    const std::optional<qint64> context = contextId(pending.context, error);
    if (!context)
        return std::nullopt;
    const JournalEvent &e = pending.event;
    std::optional<qint64> device;
    if (!e.device.isEmpty()) {
        device = deviceId(e.device, error);
        if (!device)
            return std::nullopt;
    }
    const QVariant values[] = {
        pending.uid.toRfc4122(),
        *context,
        optionalValue(device),
        optionalValue(e.port),
        e.timeMs,
        JournalEvent::kindName(e.kind),
        JournalEvent::severityName(e.severity),
        text(e.text),
        e.details.isEmpty()
            ? QVariant(QMetaType(QMetaType::QString))
            : QVariant(QString::fromUtf8(QJsonDocument(e.details).toJson(QJsonDocument::Compact)))};
    for (int i = 0; i < int(std::size(values)); ++i)
        m_insertEvent.bindValue(i, values[i]);
    return run(m_insertEvent, error);
}

bool JournalStatements::markSent(const SentMarks &marks, QSqlError *error) {
    QSqlQuery &query = marks.table == Table::Joints        ? m_markJoint
                       : marks.channel == SentChannel::Cfx ? m_markEventCfx
                                                           : m_markEvent;
    for (const qint64 id : marks.ids) {
        query.bindValue(0, id);
        if (!run(query, error))
            return false;
    }
    return true;
}

std::optional<int> JournalStatements::prune(Table table, qint64 cutoffMs, int limit,
                                            QSqlError *error) {
    QSqlQuery &query = table == Table::Joints ? m_pruneJoints : m_pruneEvents;
    query.bindValue(0, cutoffMs);
    query.bindValue(1, limit);
    if (!query.exec()) {
        *error = query.lastError();
        return std::nullopt;
    }
    const int deleted = query.numRowsAffected(); // before finish(), which forgets it
    query.finish();
    return deleted;
}

void JournalStatements::forgetIds() {
    m_deviceIds.clear();
    m_contextIds.clear();
}

std::optional<qint64> JournalStatements::deviceId(const model::DeviceIdentity &device,
                                                  QSqlError *error) {
    const QString key = device.key();
    return storedId(m_deviceIds, key, {m_findDevice, {key}},
                    {m_insertDevice,
                     {key, text(device.line), optionalValue(device.address), text(device.model),
                      text(device.softwareVersion)}},
                    error);
}

std::optional<qint64> JournalStatements::contextId(const model::WorkContext &context,
                                                   QSqlError *error) {
    const QVariantList fields = {text(context.workOrder), text(context.boardSerial),
                                 text(context.operatorName)};
    return storedId(m_contextIds, contextKey(context), {m_findContext, fields},
                    {m_insertContext, fields}, error);
}

// The id `cache` knows for `key`, else the one `find` finds, else the one `insert` makes.
std::optional<qint64> JournalStatements::storedId(QHash<QString, qint64> &cache, const QString &key,
                                                  const Bound &find, const Bound &insert,
                                                  QSqlError *error) {
    if (const auto known = cache.constFind(key); known != cache.constEnd())
        return *known;
    for (int i = 0; i < find.values.size(); ++i)
        find.query.bindValue(i, find.values.at(i));
    if (!find.query.exec()) {
        *error = find.query.lastError();
        return std::nullopt;
    }
    std::optional<qint64> id;
    if (find.query.next()) {
        id = find.query.value(0).toLongLong();
        find.query.finish();
    } else {
        for (int i = 0; i < insert.values.size(); ++i)
            insert.query.bindValue(i, insert.values.at(i));
        id = run(insert.query, error);
    }
    if (id)
        cache.insert(key, *id);
    return id;
}

} // namespace tipscope::journal
