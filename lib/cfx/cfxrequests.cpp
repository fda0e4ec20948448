#include "cfxrequests.h"

#include <QCoreApplication>
#include <QSysInfo>

namespace tipscope::cfx {

using base::failure;
using base::Outcome;

namespace {

struct CfxRequestsTr {
    Q_DECLARE_TR_FUNCTIONS(Cfx)
};

// The SDK's OperatingSystem and OperatingSystemPlatform, which it writes as numbers.
int operatingSystem() {
    const QString product = QSysInfo::productType();
    if (product == QLatin1String("debian"))
        return 20; // DebianLinux
    if (product == QLatin1String("ubuntu"))
        return 15; // UbuntuLinux
    if (QSysInfo::kernelType() == QLatin1String("linux"))
        return 21; // OtherLinux
    return 0;      // Other
}

int platform() {
    const QString cpu = QSysInfo::currentCpuArchitecture();
    if (cpu == QLatin1String("x86_64"))
        return 2; // Platform64bit
    if (cpu == QLatin1String("i386"))
        return 1; // Platform32bit
    if (cpu == QLatin1String("arm64"))
        return 4; // ARM64
    if (cpu.startsWith(QLatin1String("arm")))
        return 3; // ARM32
    return 0;     // Other
}

QJsonObject topic(const QString &name, const QString &support, const QStringList &messages) {
    return {{QStringLiteral("TopicName"), name},
            {QStringLiteral("TopicSupportType"), support},
            {QStringLiteral("SupportedMessages"), QJsonArray::fromStringList(messages)}};
}

// What every TipScope endpoint publishes and answers (docs/cfx.md).
QJsonArray supportedTopics() {
    return {
        topic(QStringLiteral("CFX"), QStringLiteral("PublisherConsumer"),
              {QStringLiteral("CFX.EndpointConnected"), QStringLiteral("CFX.Heartbeat"),
               QStringLiteral("CFX.EndpointShuttingDown"), QStringLiteral("CFX.AreYouThereRequest"),
               QStringLiteral("CFX.GetEndpointInformationRequest")}),
        topic(QStringLiteral("CFX.ResourcePerformance"), QStringLiteral("Publisher"),
              {QStringLiteral("CFX.ResourcePerformance.StationStateChanged"),
               QStringLiteral("CFX.ResourcePerformance.FaultOccurred"),
               QStringLiteral("CFX.ResourcePerformance.FaultCleared")}),
        topic(QStringLiteral("CFX.Production"), QStringLiteral("Publisher"),
              {QStringLiteral("CFX.Production.WorkStarted"),
               QStringLiteral("CFX.Production.WorkCompleted")}),
        topic(QStringLiteral("CFX.Production.Processing"), QStringLiteral("Publisher"),
              {QStringLiteral("CFX.Production.Processing.UnitsProcessed")})};
}

// The endpoint a request is for: its Target, or the CFXHandle its body names.
const EndpointIdentity *endpointOf(const Envelope &request,
                                   const QList<EndpointIdentity> &endpoints) {
    const QString handle = request.target.isEmpty()
                               ? request.body.value(QStringLiteral("CFXHandle")).toString()
                               : request.target;
    for (const EndpointIdentity &endpoint : endpoints)
        if (endpoint.handle == handle)
            return &endpoint;
    return nullptr;
}

} // namespace

Message getEndpointInformationResponse(const EndpointIdentity &endpoint,
                                       const RequestPlace &place) {
    const QJsonObject information{
        {QStringLiteral("CFXHandle"), endpoint.handle},
        {QStringLiteral("CFXVersion"), QString::fromLatin1(kCfxVersion)},
        {QStringLiteral("RequestNetworkUri"), cfxText(place.networkUri)},
        {QStringLiteral("RequestTargetAddress"), cfxText(place.address)},
        {QStringLiteral("UniqueIdentifier"), endpoint.handle},
        {QStringLiteral("FriendlyName"), cfxText(endpoint.name)},
        {QStringLiteral("Vendor"), cfxText(endpoint.vendor)},
        {QStringLiteral("ModelNumber"), cfxText(endpoint.model)},
        {QStringLiteral("SerialNumber"), kCfxNull}, // TipScope does not read a station's serial
        {QStringLiteral("SoftwareVersion"),
         QStringLiteral("TipScope %1").arg(QCoreApplication::applicationVersion())},
        {QStringLiteral("FirmwareVersion"), cfxText(endpoint.firmware)},
        {QStringLiteral("OperatingSystem"), operatingSystem()},
        {QStringLiteral("OperatingSystemPlatform"), platform()},
        {QStringLiteral("OperatingSystemVersion"), cfxText(QSysInfo::productVersion())},
        {QStringLiteral("Stages"), QJsonArray()},
        {QStringLiteral("NumberOfLanes"), 0}, // a hand-soldering station has no conveyor
        {QStringLiteral("HermesInformation"), kCfxNull},
        {QStringLiteral("OperatingRequirements"), kCfxNull},
        {QStringLiteral("SupportedTopics"), supportedTopics()},
        {QStringLiteral("SupportedPCBDimensions"), kCfxNull},
        {QStringLiteral("SleepStates"), kCfxNull}};
    return {QStringLiteral("CFX.GetEndpointInformationResponse"),
            {{QStringLiteral("Result"),
              QJsonObject{{QStringLiteral("Result"), QStringLiteral("Success")},
                          {QStringLiteral("ResultCode"), 0},
                          {QStringLiteral("Message"), kCfxNull}}},
             {QStringLiteral("EndpointInformation"), information}}};
}

Outcome<Answer> answerRequest(const AmqpRequest &request, const QList<EndpointIdentity> &endpoints,
                              const RequestPlace &place) {
    const auto envelope = envelopeFromAmqp(request.body, request.contentEncoding);
    if (!envelope)
        return failure(envelope.error());
    if (request.replyTo.isEmpty())
        return failure(CfxRequestsTr::tr("A CFX request (%1) without a reply-to address: it "
                                         "cannot be answered.")
                           .arg(envelope->messageName.left(80)));
    const EndpointIdentity *endpoint = endpointOf(*envelope, endpoints);
    if (!endpoint)
        return failure(CfxRequestsTr::tr("A CFX request (%1) for \"%2\", which is no endpoint "
                                         "here.")
                           .arg(envelope->messageName.left(80), envelope->target.left(80)));
    Message message;
    if (envelope->messageName == QLatin1String("CFX.AreYouThereRequest"))
        message = areYouThereResponse(endpoint->handle, place.networkUri, place.address);
    else if (envelope->messageName == QLatin1String("CFX.GetEndpointInformationRequest"))
        message = getEndpointInformationResponse(*endpoint, place);
    else
        message = notSupportedResponse(envelope->messageName.left(200));
    Envelope answer = envelopeOf(message, endpoint->handle);
    answer.target = envelope->source;
    answer.requestId = envelope->requestId;
    AmqpMessage amqp = toAmqpMessage(answer, Codec::Raw);
    if (!request.messageId.isEmpty())
        amqp.correlationId = request.messageId;
    return Answer{request.replyTo, amqp};
}

} // namespace tipscope::cfx
