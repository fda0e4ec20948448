#include "journalselect.h"

#include <QJsonDocument>
#include <QStringList>

namespace tipscope::journal {

namespace {

// The joint and event columns, then those of their device and context.
const char kJointColumns[] =
    "SELECT j.id, j.uid, j.sent, c.work_order, c.board_serial, c.operator, d.line, d.address, "
    "d.model, d.software, j.port, j.tool, j.start_ms, j.end_ms, j.setpoint, j.lowest_tip, "
    "j.dip_depth, j.recovery_ms, j.duration_ms, j.power_peak, j.power_integral, j.verdict, "
    "j.start_uncertainty_ms, j.dip_uncertainty_k, j.recovery_uncertainty_ms, j.recovery_bounded, "
    "j.band_k, j.max_recovery_ms, j.max_dip_k FROM joints j LEFT JOIN devices d ON d.id = "
    "j.device_id "
    "LEFT JOIN contexts c ON c.id = j.context_id";
const char kEventColumns[] =
    "SELECT e.id, e.uid, e.sent, c.work_order, c.board_serial, c.operator, d.line, d.address, "
    "d.model, d.software, e.port, e.time_ms, e.kind, e.severity, e.text, e.details "
    "FROM events e LEFT JOIN devices d ON d.id = e.device_id "
    "LEFT JOIN contexts c ON c.id = e.context_id";

// Conditions joined by AND, with their values.
struct Conditions {
    QStringList terms;
    QVariantList values;

    template <typename T> void add(const char *term, const std::optional<T> &value) {
        if (!value)
            return;
        terms.append(QString::fromLatin1(term));
        values.append(QVariant::fromValue(*value));
    }
    [[nodiscard]] QString where() const {
        return terms.isEmpty() ? QString()
                               : QStringLiteral(" WHERE ") + terms.join(QStringLiteral(" AND "));
    }
};

Conditions jointConditions(const JointFilter &f) {
    Conditions c;
    c.add("j.start_ms >= ?", f.sinceMs);
    c.add("j.start_ms < ?", f.untilMs);
    c.add("j.device_id = (SELECT id FROM devices WHERE key = ?)", f.deviceKey);
    c.add("j.port = ?", f.port);
    c.add("j.tool = ?", f.tool);
    if (f.verdict)
        c.add("j.verdict = ?", std::optional(model::jointVerdictName(*f.verdict)));
    c.add("j.context_id IN (SELECT id FROM contexts WHERE work_order = ?)", f.workOrder);
    c.add("j.context_id IN (SELECT id FROM contexts WHERE board_serial = ?)", f.boardSerial);
    return c;
}

Conditions eventConditions(const EventFilter &f) {
    Conditions c;
    c.add("e.time_ms >= ?", f.sinceMs);
    c.add("e.time_ms < ?", f.untilMs);
    c.add("e.device_id = (SELECT id FROM devices WHERE key = ?)", f.deviceKey);
    c.add("e.port = ?", f.port);
    if (!f.kinds.isEmpty()) {
        QStringList marks;
        for (const JournalEvent::Kind kind : f.kinds) {
            marks.append(QStringLiteral("?"));
            c.values.append(JournalEvent::kindName(kind));
        }
        c.terms.append(QStringLiteral("e.kind IN (%1)").arg(marks.join(QLatin1Char(','))));
    }
    c.add("e.context_id IN (SELECT id FROM contexts WHERE work_order = ?)", f.workOrder);
    c.add("e.context_id IN (SELECT id FROM contexts WHERE board_serial = ?)", f.boardSerial);
    return c;
}

QString orderAndLimit(const QString &time, const QString &id, Order order, int limit) {
    const QString direction =
        order == Order::NewestFirst ? QStringLiteral("DESC") : QStringLiteral("ASC");
    QString sql = QStringLiteral(" ORDER BY %1 %3, %2 %3").arg(time, id, direction);
    if (limit > 0)
        sql += QStringLiteral(" LIMIT %1").arg(limit);
    return sql;
}

std::optional<int> optionalInt(const QVariant &value) {
    return value.isNull() ? std::nullopt : std::optional<int>(value.toInt());
}

// The columns every select starts with: id, uid, sent, the context, the device.
template <typename T> Stored<T> readCommon(const QSqlQuery &q) {
    Stored<T> s;
    s.id = q.value(0).toLongLong();
    s.uid = QUuid::fromRfc4122(q.value(1).toByteArray());
    s.sent = q.value(2).toInt() != 0;
    s.context = {q.value(3).toString(), q.value(4).toString(), q.value(5).toString()};
    return s;
}

} // namespace

model::DeviceIdentity readDevice(const QSqlQuery &q, int first) {
    return {q.value(first).toString(), optionalInt(q.value(first + 1)),
            q.value(first + 2).toString(), q.value(first + 3).toString()};
}

Select selectJoints(const JointFilter &filter) {
    const Conditions c = jointConditions(filter);
    return {QString::fromLatin1(kJointColumns) + c.where() +
                orderAndLimit(QStringLiteral("j.start_ms"), QStringLiteral("j.id"), filter.order,
                              filter.limit),
            c.values};
}

Select selectEvents(const EventFilter &filter) {
    const Conditions c = eventConditions(filter);
    return {QString::fromLatin1(kEventColumns) + c.where() +
                orderAndLimit(QStringLiteral("e.time_ms"), QStringLiteral("e.id"), filter.order,
                              filter.limit),
            c.values};
}

Select jointsWhere(const JointFilter &filter) {
    const Conditions c = jointConditions(filter);
    return {QStringLiteral(" FROM joints j") + c.where(), c.values};
}

Select selectUnsentJoints(qint64 afterId, int limit) {
    return {QString::fromLatin1(kJointColumns) +
                QStringLiteral(" WHERE j.sent = 0 AND j.id > ? ORDER BY j.id LIMIT ?"),
            {afterId, limit}};
}

Select selectUnsentEvents(qint64 afterId, int limit, SentChannel channel) {
    const QString mark =
        channel == SentChannel::Cfx ? QStringLiteral("e.cfx_sent") : QStringLiteral("e.sent");
    return {QString::fromLatin1(kEventColumns) + QStringLiteral(" WHERE ") + mark +
                QStringLiteral(" = 0 AND e.id > ? ORDER BY e.id LIMIT ?"),
            {afterId, limit}};
}

StoredJoint readJoint(const QSqlQuery &q) {
    StoredJoint s = readCommon<model::JointRecord>(q);
    model::JointRecord &j = s.record;
    j.device = readDevice(q, 6);
    j.port = q.value(10).toInt();
    j.tool = q.value(11).toString();
    j.startMs = q.value(12).toLongLong();
    j.endMs = q.value(13).toLongLong();
    j.setpoint = q.value(14).toInt();
    j.lowestTip = q.value(15).toDouble();
    j.dipDepth = q.value(16).toDouble();
    if (!q.value(17).isNull())
        j.recoveryMs = q.value(17).toLongLong();
    j.durationMs = q.value(18).toLongLong();
    j.powerPeak = q.value(19).toInt();
    j.powerIntegral = q.value(20).toDouble();
    j.verdict = model::jointVerdictFromName(q.value(21).toString())
                    .value_or(model::JointVerdict::Incomplete);
    j.startUncertaintyMs = q.value(22).toLongLong();
    j.dipUncertaintyK = q.value(23).toDouble();
    j.recoveryUncertaintyMs = q.value(24).toLongLong();
    j.recoveryBounded = q.value(25).toInt() != 0;
    if (!q.value(26).isNull())
        j.limits =
            model::JudgedLimits{q.value(26).toInt(), q.value(27).toLongLong(), q.value(28).toInt()};
    return s;
}

StoredEvent readEvent(const QSqlQuery &q) {
    StoredEvent s = readCommon<JournalEvent>(q);
    JournalEvent &e = s.record;
    if (!q.value(6).isNull())
        e.device = readDevice(q, 6);
    e.port = optionalInt(q.value(10));
    e.timeMs = q.value(11).toLongLong();
    e.kind =
        JournalEvent::kindFromName(q.value(12).toString()).value_or(JournalEvent::Kind::Status);
    e.severity = JournalEvent::severityFromName(q.value(13).toString())
                     .value_or(JournalEvent::Severity::Info);
    e.text = q.value(14).toString();
    e.details = QJsonDocument::fromJson(q.value(15).toByteArray()).object();
    return s;
}

} // namespace tipscope::journal
