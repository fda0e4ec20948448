#include "jointstatistics.h"

#include "jointexport.h"

#include <QDateTime>
#include <QJsonArray>

namespace tipscope::journal {

base::Outcome<QJsonObject> jointStatistics(const JournalReader &reader, qint64 sinceMs,
                                           qint64 untilMs) {
    JointFilter range;
    range.sinceMs = sinceMs;
    range.untilMs = untilMs;
    const auto ports = reader.recoveryByPort(range);
    if (!ports)
        return base::failure(ports.error());
    QJsonArray out;
    for (const PortRecovery &p : ports.value()) {
        JointFilter one = range;
        one.deviceKey = p.device.key();
        one.port = p.port;
        const auto verdicts = reader.verdictCounts(one);
        if (!verdicts)
            return base::failure(verdicts.error());
        QJsonObject port{{QStringLiteral("device"), p.device.description()},
                         {QStringLiteral("deviceKey"), p.device.key()},
                         {QStringLiteral("port"), p.port},
                         {QStringLiteral("joints"), double(p.joints)}};
        for (const model::JointVerdict v : model::kJointVerdicts)
            port.insert(model::jointVerdictName(v), double(verdicts.value().value(v, 0)));
        if (p.recovered > 0) {
            port.insert(QStringLiteral("recoveryMedianMs"), double(p.medianMs));
            port.insert(QStringLiteral("recoveryP95Ms"), double(p.p95Ms));
        }
        out.append(port);
    }
    return QJsonObject{{QStringLiteral("since"), utcText(sinceMs)},
                       {QStringLiteral("until"), utcText(untilMs)},
                       {QStringLiteral("ports"), out}};
}

QJsonObject lastDayOfJoints(const QString &path) {
    JournalReader reader;
    if (const auto opened = reader.open(path); !opened)
        return {{QStringLiteral("error"), opened.error()}};
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const auto statistics = jointStatistics(reader, now - kDayMs, now + 1);
    if (!statistics)
        return {{QStringLiteral("error"), statistics.error()}};
    return statistics.value();
}

} // namespace tipscope::journal
