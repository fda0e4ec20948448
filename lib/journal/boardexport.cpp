#include "boardexport.h"

#include "jointexport.h"

#include "model/joints/tipwear.h"

#include <QJsonArray>
#include <QStringList>
#include <cmath>

namespace tipscope::journal {

namespace {

// Why the record has no such figure: the same words in the JSON and the text.
// Empty when every joint of the board carries the limits it was judged by.
QString noLimits(const BoardRecord &record) {
    const int without = jointsWithoutLimits(record);
    if (without == 0)
        return {};
    return QStringLiteral("joints without the limits they were judged by (journaled before the "
                          "journal kept them): %1 of %2; a failed joint's warning among the "
                          "events names the limit it broke")
        .arg(without)
        .arg(record.joints.size());
}
const char kNoSettings[] = "the journal keeps settings only as changes made through TipScope "
                           "(writes, profile applies); changes at the station's own keys and "
                           "the settings as they stood are not in it";
const char kNoCurves[] = "the journal keeps each joint's figures, not the tip's readings, so "
                         "no curve of a joint can be drawn from it";

template <typename T, typename ToJson>
QJsonArray jsonArray(const QList<T> &items, const ToJson &toJson) {
    QJsonArray array;
    for (const T &item : items)
        array.append(toJson(item));
    return array;
}

QJsonValue optionalMs(const std::optional<qint64> &ms) {
    return ms ? QJsonValue(double(*ms)) : QJsonValue();
}

QString secondsWords(qint64 ms) {
    return QString::number(double(ms) / 1000, 'f', 2) + QStringLiteral(" s");
}

QJsonObject verdictsJson(const BoardRecord &record) {
    QJsonObject verdicts;
    for (const model::JointVerdict verdict : model::kJointVerdicts)
        verdicts.insert(model::jointVerdictName(verdict), record.verdicts.value(verdict));
    return verdicts;
}

QJsonObject tipJson(const BoardTip &tip) {
    QJsonArray setpoints;
    for (const int setpoint : tip.setpoints)
        setpoints.append(setpoint);
    return {
        {QStringLiteral("device"), tip.device.key()},
        {QStringLiteral("model"), tip.device.model},
        {QStringLiteral("address"), addressText(tip.device)},
        {QStringLiteral("port"), tip.port},
        {QStringLiteral("tool"), tip.tool},
        {QStringLiteral("joints"), tip.joints},
        {QStringLiteral("setpoints_c"), setpoints},
        {QStringLiteral("since"), tip.sinceMs ? QJsonValue(utcText(tip.sinceMs)) : QJsonValue()},
        {QStringLiteral("history_joints"), tip.historyJoints},
        {QStringLiteral("wear_window"), model::TipWear::kWindow},
        {QStringLiteral("baseline_recovery_ms"), optionalMs(tip.baselineMs)},
        {QStringLiteral("recent_recovery_ms"), optionalMs(tip.recentMs)}};
}

QString verdictsWords(const BoardRecord &record) {
    QStringList counts;
    for (const model::JointVerdict verdict : model::kJointVerdicts)
        counts.append(QStringLiteral("%1 %2")
                          .arg(record.verdicts.value(verdict))
                          .arg(model::jointVerdictName(verdict)));
    return counts.join(QStringLiteral(", "));
}

QString tipWearWords(const BoardTip &tip) {
    if (!tip.baselineMs)
        return QStringLiteral("wear: not yet known (%1 joints with this tip; its first %2 "
                              "recovered ones are the baseline)")
            .arg(tip.historyJoints)
            .arg(model::TipWear::kWindow);
    if (!tip.recentMs)
        return QStringLiteral("wear: %1 when plugged in, no joint since to compare")
            .arg(secondsWords(*tip.baselineMs));
    return QStringLiteral("wear: recovers in %1 (median of the last %2 joints), %3 when plugged "
                          "in: %4")
        .arg(secondsWords(*tip.recentMs))
        .arg(model::TipWear::kWindow)
        .arg(secondsWords(*tip.baselineMs), wearShareText(tip));
}

QString tipLine(const BoardTip &tip) {
    QStringList setpoints;
    for (const int setpoint : tip.setpoints)
        setpoints.append(QString::number(setpoint));
    return QStringLiteral("  %1 %2 P%3 %4  %5 joints at %6 °C  %7")
        .arg(tip.device.model, addressText(tip.device))
        .arg(tip.port)
        .arg(tip.tool.isEmpty() ? QStringLiteral("-") : tip.tool)
        .arg(tip.joints)
        .arg(setpoints.join(QLatin1Char('/')), tipWearWords(tip));
}

QString eventLine(const StoredEvent &stored) {
    const JournalEvent &e = stored.record;
    QString where = e.device.isEmpty()
                        ? QStringLiteral("-")
                        : QStringLiteral("%1 %2").arg(e.device.model, addressText(e.device));
    if (e.port)
        where += QStringLiteral(" P%1").arg(*e.port);
    return QStringLiteral("  %1  %2  %3 %4  %5")
        .arg(utcText(e.timeMs), where, JournalEvent::kindName(e.kind),
             JournalEvent::severityName(e.severity), e.text);
}

// What the text adds to the joints' line: how sure the start and dip are, and who made it.
QString jointDetail(const StoredJoint &stored) {
    const model::JointRecord &j = stored.record;
    QString detail = QStringLiteral("  (start ±%1 ms, dip ±%2 K")
                         .arg(j.startUncertaintyMs)
                         .arg(QString::number(j.dipUncertaintyK, 'f', 1));
    if (j.recoveryMs && !j.recoveryBounded)
        detail += QStringLiteral(", recovery ±%1 ms").arg(j.recoveryUncertaintyMs);
    detail += QLatin1Char(')');
    if (j.limits)
        detail += QStringLiteral("  limits: dip %1 K, recovery %2 s, band %3 K")
                      .arg(j.limits->maxDipK)
                      .arg(QString::number(double(j.limits->maxRecoveryMs) / 1000, 'f', 1))
                      .arg(j.limits->bandK);
    if (!stored.context.operatorName.isEmpty())
        detail += QStringLiteral("  ") + stored.context.operatorName;
    return detail;
}

} // namespace

QString wearShareText(const BoardTip &tip) {
    if (!tip.baselineMs || !tip.recentMs || *tip.baselineMs <= 0)
        return {};
    const double share = 100.0 * double(*tip.recentMs - *tip.baselineMs) / double(*tip.baselineMs);
    const long rounded = std::lround(share);
    return QStringLiteral("%1%2 %").arg(rounded > 0 ? QStringLiteral("+") : QString()).arg(rounded);
}

QJsonObject boardJson(const BoardRecord &record, const QString &software) {
    const bool empty = record.isEmpty();
    QJsonObject notHeld{{QStringLiteral("settings"), QString::fromLatin1(kNoSettings)},
                        {QStringLiteral("curves"), QString::fromLatin1(kNoCurves)}};
    if (const QString limits = noLimits(record); !limits.isEmpty())
        notHeld.insert(QStringLiteral("limits"), limits);
    return {{QStringLiteral("board_serial"), record.serial},
            {QStringLiteral("result"), boardResultName(record.result)},
            {QStringLiteral("first"), empty ? QJsonValue() : QJsonValue(utcText(record.firstMs))},
            {QStringLiteral("last"), empty ? QJsonValue() : QJsonValue(utcText(record.lastMs))},
            {QStringLiteral("work_orders"), QJsonArray::fromStringList(record.workOrders)},
            {QStringLiteral("operators"), QJsonArray::fromStringList(record.operators)},
            {QStringLiteral("verdicts"), verdictsJson(record)},
            {QStringLiteral("joints"), jsonArray(record.joints, jointJson)},
            {QStringLiteral("events"), jsonArray(record.events, eventJson)},
            {QStringLiteral("tips"), jsonArray(record.tips, tipJson)},
            {QStringLiteral("profiles_before"), jsonArray(record.profilesBefore, eventJson)},
            {QStringLiteral("not_in_journal"), notHeld},
            {QStringLiteral("software"), software}};
}

QString boardCsv(const BoardRecord &record) {
    QString csv = jointCsvHeader() + QLatin1Char('\n');
    for (const StoredJoint &j : record.joints)
        csv += jointCsvRow(j) + QLatin1Char('\n');
    return csv;
}

QString boardText(const BoardRecord &record, const QString &software) {
    QStringList lines{QStringLiteral("board %1").arg(record.serial),
                      QStringLiteral("result: %1 (%2 joints: %3)")
                          .arg(boardResultName(record.result))
                          .arg(record.joints.size())
                          .arg(verdictsWords(record))};
    if (!record.isEmpty())
        lines.append(
            QStringLiteral("made: %1 .. %2").arg(utcText(record.firstMs), utcText(record.lastMs)));
    lines.append(QStringLiteral("work order: ") + record.workOrders.join(QStringLiteral(", ")));
    lines.append(QStringLiteral("operator: ") + record.operators.join(QStringLiteral(", ")));
    lines.append(QStringLiteral("joints:"));
    for (const StoredJoint &j : record.joints)
        lines.append(QStringLiteral("  ") + jointTextLine(j) + jointDetail(j));
    lines.append(QStringLiteral("tips:"));
    for (const BoardTip &tip : record.tips)
        lines.append(tipLine(tip));
    // An empty list says so, rather than a heading with nothing under it.
    const auto listOf = [&lines](const QString &heading, const QList<StoredEvent> &events) {
        lines.append(heading);
        for (const StoredEvent &e : events)
            lines.append(eventLine(e));
        if (events.isEmpty())
            lines.append(QStringLiteral("  none in the journal"));
    };
    listOf(QStringLiteral("last profile applied before the board:"), record.profilesBefore);
    listOf(QStringLiteral("events:"), record.events);
    lines.append(QStringLiteral("not in the journal:"));
    if (const QString limits = noLimits(record); !limits.isEmpty())
        lines.append(QStringLiteral("  limits: ") + limits);
    lines.append(QStringLiteral("  settings: ") + QString::fromLatin1(kNoSettings));
    lines.append(QStringLiteral("  curves: ") + QString::fromLatin1(kNoCurves));
    lines.append(QStringLiteral("software: TipScope ") + software);
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace tipscope::journal
