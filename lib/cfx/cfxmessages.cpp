#include "cfxmessages.h"

#include <QRegularExpression>

namespace tipscope::cfx {

namespace {

using Kind = journal::JournalEvent::Kind;
using Severity = journal::JournalEvent::Severity;

QString handlePart(const QString &part) {
    static const QRegularExpression kOther(QStringLiteral("[^A-Za-z0-9_-]+"));
    QString cleaned = part.trimmed();
    cleaned.replace(kOther, QStringLiteral("_"));
    return cleaned.isEmpty() ? QStringLiteral("unknown") : cleaned;
}

// Which FaultCause (CFX/Structures/FaultCause.cs) a kind of station error is nearest to.
QString causeOf(Kind kind) {
    switch (kind) {
    case Kind::StationError:
        return QStringLiteral("ElectricalFailure");
    case Kind::FeederError:
        return QStringLiteral("MechanicalFailure");
    default:
        return QStringLiteral("ProcessError");
    }
}

QJsonObject requestResult(const QString &result, const QString &message) {
    return {{QStringLiteral("Result"), result},
            {QStringLiteral("ResultCode"), 0},
            {QStringLiteral("Message"), cfxText(message)}};
}

} // namespace

Envelope envelopeOf(const Message &message, const QString &source, const QUuid &uniqueId,
                    const QDateTime &time) {
    Envelope envelope;
    envelope.messageName = message.name;
    envelope.body = message.body;
    envelope.source = source;
    envelope.uniqueId = uniqueId;
    envelope.timeStamp = time;
    return envelope;
}

const E10Mapping kE10Mapping[6] = {
    {StationCondition::Error, E10State::UnscheduledDowntime,
     "a station, port or feeder error stops the work until someone mends it"},
    {StationCondition::LinkLost, E10State::StandbyNoHost,
     "TipScope, the station's host, cannot reach it: its state is unknown"},
    {StationCondition::Working, E10State::ProductiveRegularWork,
     "a tool is out of its stand, at soldering temperature"},
    {StationCondition::InStand, E10State::StandbyNoProduct,
     "every tool rests in its stand, ready to work"},
    {StationCondition::Sleep, E10State::StandbyNoOperator,
     "the tools rested long enough for the station to lower their temperature"},
    {StationCondition::Hibernation, E10State::StandbyNoOperator,
     "the tools rested so long that the station switched their heaters off"},
};

E10State e10StateOf(StationCondition condition) {
    for (const E10Mapping &row : kE10Mapping)
        if (row.condition == condition)
            return row.state;
    return E10State::UnscheduledDowntime;
}

QString conditionName(StationCondition condition) {
    switch (condition) {
    case StationCondition::Error:
        return QStringLiteral("error");
    case StationCondition::LinkLost:
        return QStringLiteral("link lost");
    case StationCondition::Working:
        return QStringLiteral("working");
    case StationCondition::InStand:
        return QStringLiteral("in the stand");
    case StationCondition::Sleep:
        return QStringLiteral("sleep");
    case StationCondition::Hibernation:
        return QStringLiteral("hibernation");
    }
    return {};
}

QString endpointHandle(const QString &vendor, const QString &model, const QString &unit) {
    return QStringList{handlePart(vendor), handlePart(model), handlePart(unit)}.join(
        QLatin1Char('.'));
}

Message endpointConnected(const QString &handle, const QString &requestUri,
                          const QString &requestAddress) {
    return {QStringLiteral("CFX.EndpointConnected"),
            {{QStringLiteral("CFXHandle"), handle},
             {QStringLiteral("RequestNetworkUri"), cfxText(requestUri)},
             {QStringLiteral("RequestTargetAddress"), cfxText(requestAddress)}}};
}

Message heartbeat(const QString &handle, qint64 periodMs, const QJsonValue &activeFaults) {
    return {QStringLiteral("CFX.Heartbeat"),
            {{QStringLiteral("CFXHandle"), handle},
             {QStringLiteral("HeartbeatFrequency"), cfxTimeSpan(periodMs)},
             {QStringLiteral("ActiveFaults"), activeFaults},
             {QStringLiteral("ActiveRecipes"), QJsonValue(QJsonValue::Null)}}};
}

Message endpointShuttingDown(const QString &handle) {
    return {QStringLiteral("CFX.EndpointShuttingDown"), {{QStringLiteral("CFXHandle"), handle}}};
}

Message stationStateChanged(StationCondition before, std::optional<qint64> oldDurationMs,
                            StationCondition after, const QJsonObject &relatedFault) {
    return {
        QStringLiteral("CFX.ResourcePerformance.StationStateChanged"),
        {{QStringLiteral("OldState"), QString::number(int(e10StateOf(before)))},
         {QStringLiteral("OldStateDuration"),
          oldDurationMs ? QJsonValue(cfxTimeSpan(*oldDurationMs)) : QJsonValue(QJsonValue::Null)},
         {QStringLiteral("NewState"), QString::number(int(e10StateOf(after)))},
         {QStringLiteral("RelatedFault"),
          relatedFault.isEmpty() ? QJsonValue(QJsonValue::Null) : QJsonValue(relatedFault)}}};
}

bool isFaultEvent(const journal::JournalEvent &event) {
    return event.kind == Kind::StationError || event.kind == Kind::PortError ||
           event.kind == Kind::FeederError;
}

QString faultPlace(const journal::JournalEvent &event) {
    return QStringLiteral("%1/%2/%3")
        .arg(event.device.key(), journal::JournalEvent::kindName(event.kind))
        .arg(event.port.value_or(0));
}

QJsonObject fault(const journal::JournalEvent &event, const QUuid &occurrenceId) {
    const QString code = event.port && *event.port > 0
                             ? QStringLiteral("%1 %2")
                                   .arg(journal::JournalEvent::kindName(event.kind))
                                   .arg(*event.port)
                             : journal::JournalEvent::kindName(event.kind);
    return {{QStringLiteral("TransactionID"), QJsonValue(QJsonValue::Null)},
            {QStringLiteral("Cause"), causeOf(event.kind)},
            {QStringLiteral("Severity"), event.severity == Severity::Error
                                             ? QStringLiteral("Error")
                                             : QStringLiteral("Warning")},
            {QStringLiteral("FaultCode"), code},
            {QStringLiteral("FaultOccurrenceId"), occurrenceId.toString(QUuid::WithoutBraces)},
            {QStringLiteral("Lane"), QJsonValue(QJsonValue::Null)},
            {QStringLiteral("Stage"), QJsonValue(QJsonValue::Null)},
            {QStringLiteral("SideLocation"), QStringLiteral("Unknown")},
            {QStringLiteral("AccessType"), QStringLiteral("Unknown")},
            {QStringLiteral("Description"), event.text},
            {QStringLiteral("DescriptionTranslations"), QJsonObject()},
            {QStringLiteral("OccurredAt"),
             cfxDateTime(QDateTime::fromMSecsSinceEpoch(event.timeMs, Qt::UTC))},
            {QStringLiteral("DueDateTime"), QJsonValue(QJsonValue::Null)}};
}

Message faultOccurred(const QJsonObject &fault) {
    return {QStringLiteral("CFX.ResourcePerformance.FaultOccurred"),
            {{QStringLiteral("Fault"), fault}}};
}

Message faultCleared(const QUuid &occurrenceId) {
    return {QStringLiteral("CFX.ResourcePerformance.FaultCleared"),
            {{QStringLiteral("FaultOccurrenceId"), occurrenceId.toString(QUuid::WithoutBraces)},
             {QStringLiteral("Operator"), QJsonValue(QJsonValue::Null)}}};
}

Message areYouThereResponse(const QString &handle, const QString &requestUri,
                            const QString &requestAddress) {
    return {QStringLiteral("CFX.AreYouThereResponse"),
            {{QStringLiteral("Result"), requestResult(QStringLiteral("Success"), QString())},
             {QStringLiteral("CFXHandle"), handle},
             {QStringLiteral("RequestNetworkUri"), cfxText(requestUri)},
             {QStringLiteral("RequestTargetAddress"), cfxText(requestAddress)}}};
}

Message notSupportedResponse(const QString &request) {
    return {QStringLiteral("CFX.NotSupportedResponse"),
            {{QStringLiteral("RequestResult"),
              requestResult(QStringLiteral("Failed"),
                            QStringLiteral("Not implemented message: %1").arg(request))}}};
}

} // namespace tipscope::cfx
