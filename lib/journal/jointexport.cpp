#include "jointexport.h"

#include "base/csv.h"

#include <QDateTime>
#include <QJsonArray>
#include <QStringList>
#include <cmath>

namespace tipscope::journal {

namespace {
const QStringList kFields = {QStringLiteral("ts"),
                             QStringLiteral("end"),
                             QStringLiteral("id"),
                             QStringLiteral("device"),
                             QStringLiteral("line"),
                             QStringLiteral("address"),
                             QStringLiteral("model"),
                             QStringLiteral("software"),
                             QStringLiteral("port"),
                             QStringLiteral("tool"),
                             QStringLiteral("setpoint_c"),
                             QStringLiteral("lowest_c"),
                             QStringLiteral("dip_k"),
                             QStringLiteral("recovery_ms"),
                             QStringLiteral("duration_ms"),
                             QStringLiteral("power_peak_pct"),
                             QStringLiteral("power_integral_pct_s"),
                             QStringLiteral("verdict"),
                             QStringLiteral("work_order"),
                             QStringLiteral("board_serial"),
                             QStringLiteral("operator"),
                             QStringLiteral("start_uncertainty_ms"),
                             QStringLiteral("dip_uncertainty_k"),
                             QStringLiteral("recovery_uncertainty_ms"),
                             QStringLiteral("recovery_bounded"),
                             QStringLiteral("band_k"),
                             QStringLiteral("max_recovery_ms"),
                             QStringLiteral("max_dip_k")};

double tenths(double value) {
    return std::round(value * 10) / 10;
}

QJsonValue addressJson(const model::DeviceIdentity &device) {
    return device.address ? QJsonValue(addressText(device)) : QJsonValue();
}

QString csvField(const QJsonValue &value) {
    QString text;
    if (value.isDouble())
        text = QString::number(value.toDouble(), 'g', 12);
    else if (value.isBool())
        text = value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    else if (value.isString())
        text = value.toString();
    // The one CSV cell rule of every export (model/io/csv.h): a line break inside a cell becomes
    // a space, so that one record stays one line for every tool that reads it.
    return base::csv::quoted(text);
}
} // namespace

QString addressText(const model::DeviceIdentity &device) {
    return device.address ? QStringLiteral("%1").arg(*device.address, 2, 10, QLatin1Char('0'))
                          : QStringLiteral("--");
}

QString utcText(qint64 msSinceEpoch) {
    return QDateTime::fromMSecsSinceEpoch(msSinceEpoch, Qt::UTC).toString(Qt::ISODateWithMs);
}

QJsonObject jointJson(const StoredJoint &stored) {
    const model::JointRecord &j = stored.record;
    const auto optional = [](const auto &v) { return v ? QJsonValue(double(*v)) : QJsonValue(); };
    return {{kFields[0], utcText(j.startMs)},
            {kFields[1], utcText(j.endMs)},
            {kFields[2], stored.uid.toString(QUuid::WithoutBraces)},
            {kFields[3], j.device.key()},
            {kFields[4], j.device.line},
            {kFields[5], addressJson(j.device)},
            {kFields[6], j.device.model},
            {kFields[7], j.device.softwareVersion},
            {kFields[8], j.port},
            {kFields[9], j.tool},
            {kFields[10], j.setpoint},
            {kFields[11], tenths(j.lowestTip)},
            {kFields[12], tenths(j.dipDepth)},
            {kFields[13], optional(j.recoveryMs)},
            {kFields[14], double(j.durationMs)},
            {kFields[15], j.powerPeak},
            {kFields[16], std::round(j.powerIntegral * 1000) / 1000}, // no float noise
            {kFields[17], model::jointVerdictName(j.verdict)},
            {kFields[18], stored.context.workOrder},
            {kFields[19], stored.context.boardSerial},
            {kFields[20], stored.context.operatorName},
            {kFields[21], double(j.startUncertaintyMs)},
            {kFields[22], tenths(j.dipUncertaintyK)},
            {kFields[23], double(j.recoveryUncertaintyMs)},
            {kFields[24], j.recoveryBounded},
            {kFields[25], j.limits ? QJsonValue(j.limits->bandK) : QJsonValue()},
            {kFields[26], j.limits ? QJsonValue(double(j.limits->maxRecoveryMs)) : QJsonValue()},
            {kFields[27], j.limits ? QJsonValue(j.limits->maxDipK) : QJsonValue()}};
}

QString jointCsvHeader() {
    return kFields.join(QLatin1Char(','));
}

QString jointCsvRow(const StoredJoint &joint) {
    const QJsonObject o = jointJson(joint);
    QStringList cells;
    for (const QString &field : kFields)
        cells.append(csvField(o.value(field)));
    return cells.join(QLatin1Char(','));
}

QString jointTextLine(const StoredJoint &stored) {
    const model::JointRecord &j = stored.record;
    QString line =
        QStringLiteral("%1  %2 %3 P%4 %5  %6 °C  lowest %7 °C  dip %8 K  recovery %9")
            .arg(utcText(j.startMs), j.device.model, addressText(j.device))
            .arg(j.port)
            .arg(j.tool.isEmpty() ? QStringLiteral("-") : j.tool)
            .arg(j.setpoint)
            .arg(QString::number(j.lowestTip, 'f', 1), QString::number(j.dipDepth, 'f', 1))
            .arg(model::recoveryWords(j));
    line += QStringLiteral("  ") + model::jointVerdictName(j.verdict);
    if (!stored.context.workOrder.isEmpty())
        line += QStringLiteral("  ") + stored.context.workOrder;
    return line;
}

QJsonObject eventJson(const StoredEvent &stored) {
    const JournalEvent &e = stored.record;
    return {{QStringLiteral("ts"), utcText(e.timeMs)},
            {QStringLiteral("id"), stored.uid.toString(QUuid::WithoutBraces)},
            {QStringLiteral("kind"), JournalEvent::kindName(e.kind)},
            {QStringLiteral("severity"), JournalEvent::severityName(e.severity)},
            {QStringLiteral("device"), e.device.isEmpty() ? QJsonValue() : e.device.key()},
            {QStringLiteral("address"), addressJson(e.device)},
            {QStringLiteral("model"), e.device.model},
            {QStringLiteral("port"), e.port ? QJsonValue(*e.port) : QJsonValue()},
            {QStringLiteral("text"), e.text},
            {QStringLiteral("details"), e.details},
            {QStringLiteral("work_order"), stored.context.workOrder},
            {QStringLiteral("board_serial"), stored.context.boardSerial},
            {QStringLiteral("operator"), stored.context.operatorName}};
}

} // namespace tipscope::journal
