#include "cfxtap.h"

#include "benchsupport.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

namespace tipscope::bench {

namespace {

qint64 stampOf(const QString &text) {
    const QDateTime time = QDateTime::fromString(text, Qt::ISODateWithMs);
    return time.isValid() ? time.toMSecsSinceEpoch() : 0;
}

QStringList jointIdsOf(const QJsonObject &body) {
    // UnitsProcessed: each unit's GenericProcessData holds one stage a joint (docs/cfx.md).
    QStringList ids;
    for (const QJsonValue &unit : body.value(QStringLiteral("UnitProcessData")).toArray()) {
        const QJsonArray stages = unit.toObject()
                                      .value(QStringLiteral("UnitProcessData"))
                                      .toObject()
                                      .value(QStringLiteral("StageData"))
                                      .toArray();
        for (const QJsonValue &stage : stages)
            for (const QJsonValue &parameter :
                 stage.toObject().value(QStringLiteral("Parameters")).toArray())
                if (parameter.toObject().value(QStringLiteral("Name")).toString() ==
                    QLatin1String("JointId"))
                    ids.append(parameter.toObject().value(QStringLiteral("Value")).toString());
    }
    return ids;
}

} // namespace

CfxTap::CfxTap()
    : m_consumer([this](const QByteArray &line) { take(line); }) {}

QString CfxTap::skipReason() {
    return testing::CfxConsumerProcess::skipReason();
}

bool CfxTap::start(const QString &url, const QString &source, QString *error) {
    QProcess &process = m_consumer.process();
    QObject::connect(&process, &QProcess::readyReadStandardOutput, &process, [this] { read(); });
    // As many messages as a run can make, and a deadline past any run: the bench ends it.
    m_consumer.start(url, source, 1'000'000'000, 86400,
                     {QStringLiteral("--retry-max-s"), QStringLiteral("0.5")});
    if (!runUntil([&] { return m_consumer.isReady() || process.state() == QProcess::NotRunning; },
                  30000) ||
        !m_consumer.isReady()) {
        *error = QStringLiteral("the CFX consumer did not attach to %1").arg(source);
        return false;
    }
    return true;
}

void CfxTap::take(const QByteArray &line) {
    if (line.startsWith("BAD: transport")) {
        ++m_transportErrors; // the broker's outage, ridden out by connecting again
        return;
    }
    if (line.startsWith("BAD:")) {
        m_complaints.append(QString::fromUtf8(line));
        return;
    }
    if (!line.startsWith('{'))
        return;
    const QJsonObject printed = QJsonDocument::fromJson(line).object();
    const QJsonObject envelope = printed.value(QStringLiteral("envelope")).toObject();
    const QJsonObject body = envelope.value(QStringLiteral("MessageBody")).toObject();
    TappedMessage m;
    m.name = envelope.value(QStringLiteral("MessageName")).toString();
    m.source = envelope.value(QStringLiteral("Source")).toString();
    m.uniqueId = envelope.value(QStringLiteral("UniqueID")).toString();
    m.stampMs = stampOf(envelope.value(QStringLiteral("TimeStamp")).toString());
    m.arrivedMs = qint64(printed.value(QStringLiteral("arrived_ms")).toDouble());
    // The SDK spells it TransactionID in WorkStarted and TransactionId in the others.
    m.transaction = body.value(QStringLiteral("TransactionID")).toString();
    if (m.transaction.isEmpty())
        m.transaction = body.value(QStringLiteral("TransactionId")).toString();
    if (m.name == QLatin1String("CFX.Production.WorkStarted")) {
        m.board = body.value(QStringLiteral("PrimaryIdentifier")).toString();
        QStringList &at = m_startedAt[m.board];
        if (!at.contains(m.source))
            at.append(m.source);
    }
    if (m.name == QLatin1String("CFX.Production.Processing.UnitsProcessed"))
        m.jointIds = jointIdsOf(body);
    m_messages.append(m);
}

int CfxTap::connectedSince(qint64 sinceMs) const {
    QSet<QString> endpoints;
    for (const TappedMessage &m : m_messages)
        if (m.arrivedMs >= sinceMs && m.name == QLatin1String("CFX.EndpointConnected"))
            endpoints.insert(m.source);
    return int(endpoints.size());
}

} // namespace tipscope::bench
