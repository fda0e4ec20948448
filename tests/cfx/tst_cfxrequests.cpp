// Answers to requests on an endpoint's queue, without a broker: what the SDK's requester gets
// back for each request, and no answer, only the reason, for a request that is damaged, too
// large, names no endpoint here or says nowhere to answer.
#include "cfx/cfxrequests.h"
#include "testmain.h"

#include <QJsonDocument>
#include <QTest>

namespace tst_cfxrequests {

using namespace tipscope;
using namespace tipscope::cfx;

namespace {

const QList<EndpointIdentity> kEndpoints{
    {QStringLiteral("JBC.DME-2C.cell-1-1"), QStringLiteral("JBC"), QStringLiteral("DME-2C"),
     QStringLiteral("cell-1 01"), QStringLiteral("9996780")},
    {QStringLiteral("JBC.SFR-A.cell-1-10"), QStringLiteral("JBC"), QStringLiteral("SFR-A"),
     QStringLiteral("cell-1 10"), QStringLiteral("1234")}};
const RequestPlace kPlace{QStringLiteral("amqp://broker:5672"), QStringLiteral("/queue/requests")};

AmqpRequest request(const QString &name, const QString &target) {
    Envelope envelope;
    envelope.messageName = name;
    envelope.timeStamp = QDateTime::currentDateTimeUtc();
    envelope.uniqueId = QUuid::createUuid();
    envelope.source = QStringLiteral("MES.Line.1");
    envelope.target = target;
    envelope.requestId = QStringLiteral("REQUEST-42");
    envelope.body = {{QStringLiteral("CFXHandle"), target}};
    return {envelope.toBytes(), QString(), QStringLiteral("command-request"),
            QStringLiteral("/queue/mes-answers")};
}

QJsonObject envelopeOf(const Answer &answer) {
    return QJsonDocument::fromJson(answer.message.body).object();
}

} // namespace

class TstCfxRequests : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void areYouThereIsAnsweredByTheEndpointItNames() {
        const auto answer = answerRequest(
            request(QStringLiteral("CFX.AreYouThereRequest"), kEndpoints.at(1).handle), kEndpoints,
            kPlace);
        QVERIFY2(answer, qPrintable(answer.error()));
        QCOMPARE(answer->address, QStringLiteral("/queue/mes-answers"));
        const QJsonObject envelope = envelopeOf(*answer);
        QCOMPARE(envelope.value(QStringLiteral("MessageName")).toString(),
                 QStringLiteral("CFX.AreYouThereResponse"));
        QCOMPARE(envelope.value(QStringLiteral("Source")).toString(), kEndpoints.at(1).handle);
        QCOMPARE(envelope.value(QStringLiteral("Target")).toString(), QStringLiteral("MES.Line.1"));
        QCOMPARE(envelope.value(QStringLiteral("RequestID")).toString(),
                 QStringLiteral("REQUEST-42"));
        const QJsonObject body = envelope.value(QStringLiteral("MessageBody")).toObject();
        QCOMPARE(body.value(QStringLiteral("RequestTargetAddress")).toString(), kPlace.address);
        QCOMPARE(body.value(QStringLiteral("Result"))
                     .toObject()
                     .value(QStringLiteral("Result"))
                     .toString(),
                 QStringLiteral("Success"));
        // As the SDK's answers arrive: uncompressed, to the requester, tied to its message.
        QVERIFY(answer->message.contentEncoding.isEmpty());
        QCOMPARE(answer->message.to, QStringLiteral("MES.Line.1"));
        QCOMPARE(answer->message.correlationId, QStringLiteral("command-request"));
    }

    void endpointInformationSaysWhatTheEndpointIsAndSpeaks() {
        const auto answer = answerRequest(
            request(QStringLiteral("CFX.GetEndpointInformationRequest"), kEndpoints.at(0).handle),
            kEndpoints, kPlace);
        QVERIFY2(answer, qPrintable(answer.error()));
        const QJsonObject information = envelopeOf(*answer)
                                            .value(QStringLiteral("MessageBody"))
                                            .toObject()
                                            .value(QStringLiteral("EndpointInformation"))
                                            .toObject();
        QCOMPARE(information.value(QStringLiteral("ModelNumber")).toString(),
                 QStringLiteral("DME-2C"));
        QCOMPARE(information.value(QStringLiteral("FirmwareVersion")).toString(),
                 QStringLiteral("9996780"));
        QCOMPARE(information.value(QStringLiteral("CFXVersion")).toString(), QStringLiteral("2.1"));
        // OperatingSystem and its platform have no converter in the SDK: numbers.
        QVERIFY(information.value(QStringLiteral("OperatingSystem")).isDouble());
        QVERIFY(information.value(QStringLiteral("OperatingSystemPlatform")).isDouble());
        QStringList topics;
        for (const QJsonValue &topic :
             information.value(QStringLiteral("SupportedTopics")).toArray())
            topics.append(topic.toObject().value(QStringLiteral("TopicName")).toString());
        QVERIFY2(topics.contains(QStringLiteral("CFX.Production.Processing")),
                 qPrintable(topics.join(',')));
    }

    void anyOtherRequestIsNotSupported() {
        const auto answer =
            answerRequest(request(QStringLiteral("CFX.Production.GetActiveRecipeRequest"),
                                  kEndpoints.at(0).handle),
                          kEndpoints, kPlace);
        QVERIFY2(answer, qPrintable(answer.error()));
        const QJsonObject result = envelopeOf(*answer)
                                       .value(QStringLiteral("MessageBody"))
                                       .toObject()
                                       .value(QStringLiteral("RequestResult"))
                                       .toObject();
        QCOMPARE(result.value(QStringLiteral("Result")).toString(), QStringLiteral("Failed"));
        QVERIFY(result.value(QStringLiteral("Message"))
                    .toString()
                    .contains(QLatin1String("GetActiveRecipeRequest")));
    }

    void aRequestThatCannotBeAnsweredSaysWhy_data() {
        QTest::addColumn<QByteArray>("body");
        QTest::addColumn<QString>("encoding");
        QTest::addColumn<QString>("replyTo");
        QTest::addColumn<QString>("why");
        const AmqpRequest good =
            request(QStringLiteral("CFX.AreYouThereRequest"), kEndpoints.at(0).handle);
        const AmqpRequest elsewhere =
            request(QStringLiteral("CFX.AreYouThereRequest"), QStringLiteral("ACME.X.1"));
        QTest::newRow("not JSON") << QByteArray("{\"MessageName\": ") << QString() << good.replyTo
                                  << "JSON";
        QTest::newRow("too large")
            << QByteArray(kMaxRequestBytes + 1, ' ') << QString() << good.replyTo << "larger";
        QTest::newRow("not gzip") << good.body << QStringLiteral("gzip") << good.replyTo << "gzip";
        QTest::newRow("nowhere to answer") << good.body << QString() << QString() << "reply-to";
        QTest::newRow("another endpoint's")
            << elsewhere.body << QString() << good.replyTo << "ACME.X.1";
    }
    void aRequestThatCannotBeAnsweredSaysWhy() {
        QFETCH(QByteArray, body);
        QFETCH(QString, encoding);
        QFETCH(QString, replyTo);
        QFETCH(QString, why);
        const auto answer =
            answerRequest({body, encoding, QStringLiteral("id"), replyTo}, kEndpoints, kPlace);
        QVERIFY(!answer);
        QVERIFY2(answer.error().contains(why), qPrintable(answer.error()));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TstCfxRequests)

} // namespace tst_cfxrequests
#include "tst_cfxrequests.moc"
