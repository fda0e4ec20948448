// The CFX envelope and its AMQP message, held against what the IPC's SDK writes
// (CFX/CFXEnvelope.cs, CFX/Transport/AmqpUtilities.cs).
#include "cfx/cfxenvelope.h"
#include "testmain.h"

#include <QJsonDocument>
#include <QTest>

namespace tst_cfxenvelope {

using namespace tipscope::cfx;

class TstCfxEnvelope : public QObject {
    Q_OBJECT

    static Envelope sample() {
        Envelope envelope;
        envelope.messageName = QStringLiteral("CFX.ResourcePerformance.FaultOccurred");
        envelope.timeStamp = QDateTime(QDate(2026, 12, 6), QTime(14, 45, 1, 250), Qt::UTC);
        envelope.uniqueId = QUuid(QStringLiteral("3de0cfce-42f4-4302-982b-96dba4ec3de0"));
        envelope.source = QStringLiteral("JBC.DDE.L1-3");
        envelope.body = {{QStringLiteral("Fault"), QJsonObject()}};
        return envelope;
    }

private Q_SLOTS:
    void envelopeHasEveryFieldTheSdkWrites() {
        const QJsonObject json = sample().toJson();
        QCOMPARE(json.value(QStringLiteral("MessageName")).toString(),
                 QStringLiteral("CFX.ResourcePerformance.FaultOccurred"));
        QCOMPARE(json.value(QStringLiteral("Version")).toString(), QStringLiteral("2.1"));
        QCOMPARE(json.value(QStringLiteral("TimeStamp")).toString(),
                 QStringLiteral("2026-12-06T14:45:01.250Z"));
        QCOMPARE(json.value(QStringLiteral("UniqueID")).toString(),
                 QStringLiteral("3de0cfce-42f4-4302-982b-96dba4ec3de0"));
        QCOMPARE(json.value(QStringLiteral("Source")).toString(), QStringLiteral("JBC.DDE.L1-3"));
        QVERIFY(json.value(QStringLiteral("Target")).isNull());
        QVERIFY(json.value(QStringLiteral("RequestID")).isNull());
    }

    void bodyCarriesTheSdkTypeName() {
        const QJsonObject body = sample().toJson().value(QStringLiteral("MessageBody")).toObject();
        QCOMPARE(body.value(QStringLiteral("$type")).toString(),
                 QStringLiteral("CFX.ResourcePerformance.FaultOccurred, CFX"));
        QVERIFY(body.contains(QStringLiteral("Fault")));
    }

    void amqpMessageHasThePropertiesTheSdkSets() {
        const AmqpMessage message = toAmqpMessage(sample(), Codec::Raw);
        QCOMPARE(message.messageId, QStringLiteral("3de0cfce-42f4-4302-982b-96dba4ec3de0"));
        QCOMPARE(message.replyTo, QStringLiteral("JBC.DDE.L1-3"));
        QCOMPARE(message.contentType, QStringLiteral("application/json; charset=\"utf-8\""));
        QVERIFY(message.contentEncoding.isEmpty());
        QCOMPARE(message.subject,
                 QStringLiteral("JBC.DDE.L1-3.CFX.ResourcePerformance.FaultOccurred"));
        QCOMPARE(message.creationTimeMs, sample().timeStamp.toMSecsSinceEpoch());
        QCOMPARE(message.applicationProperties.value(QStringLiteral("cfx-topic")),
                 QStringLiteral("CFX.ResourcePerformance"));
        QCOMPARE(message.applicationProperties.value(QStringLiteral("cfx-message")),
                 QStringLiteral("CFX.ResourcePerformance.FaultOccurred"));
        QCOMPARE(message.applicationProperties.value(QStringLiteral("cfx-handle")),
                 QStringLiteral("JBC.DDE.L1-3"));
        QVERIFY(message.applicationProperties.contains(QStringLiteral("cfx-target")));
        QVERIFY(message.applicationProperties.value(QStringLiteral("cfx-target")).isNull());
        QCOMPARE(QJsonDocument::fromJson(message.body).object(), sample().toJson());
    }

    void gzipBodyUnpacksToTheSameEnvelope() {
        const AmqpMessage message = toAmqpMessage(sample(), Codec::Gzip);
        QCOMPARE(message.contentEncoding, QStringLiteral("gzip"));
        QVERIFY(message.body.startsWith("\x1f\x8b")); // the gzip magic, not zlib's header
        const auto back = envelopeFromAmqp(message.body, message.contentEncoding);
        QVERIFY2(back.ok(), qPrintable(back.error()));
        QCOMPARE(back->uniqueId, sample().uniqueId);
        QCOMPARE(back->body, sample().body);
        QCOMPARE(back->timeStamp, sample().timeStamp);
    }

    void damagedOrHugeGzipIsRefused() {
        QVERIFY(!gunzip(QByteArray("\x1f\x8b\x08\x00garbage", 12), 1024).ok());
        const QByteArray big = gzip(QByteArray(100000, 'a'));
        QVERIFY(gunzip(big, 200000).ok());
        QVERIFY(!gunzip(big, 1000).ok());
    }

    void timeSpansReadAsDotNetWritesThem_data() {
        QTest::addColumn<qint64>("ms");
        QTest::addColumn<QString>("text");
        QTest::newRow("a minute") << qint64(60000) << QStringLiteral("00:01:00");
        QTest::newRow("fraction") << qint64(25123) << QStringLiteral("00:00:25.1230000");
        QTest::newRow("days") << qint64(93784000) << QStringLiteral("1.02:03:04");
    }
    void timeSpansReadAsDotNetWritesThem() {
        QFETCH(qint64, ms);
        QFETCH(QString, text);
        QCOMPARE(cfxTimeSpan(ms), text);
    }

    void receivedRequestIsReadBack() {
        const QByteArray request =
            R"({"MessageName":"CFX.AreYouThereRequest","Version":"2.1","TimeStamp":"2026-12-06T14:45:01.250Z",)"
            R"("UniqueID":"ea170e0a-43fb-4b02-af2c-928a8401dd51","Source":"MES.1","Target":"JBC.DDE.L1-3",)"
            R"("RequestID":"r-1","MessageBody":{"$type":"CFX.AreYouThereRequest, CFX","CFXHandle":"JBC.DDE.L1-3"}})";
        const auto envelope = Envelope::fromBytes(request);
        QVERIFY2(envelope.ok(), qPrintable(envelope.error()));
        QCOMPARE(envelope->messageName, QStringLiteral("CFX.AreYouThereRequest"));
        QCOMPARE(envelope->requestId, QStringLiteral("r-1"));
        QCOMPARE(envelope->source, QStringLiteral("MES.1"));
        QVERIFY(!envelope->body.contains(QStringLiteral("$type")));
    }

    void badRequestsAreRefusedWithAReason_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("not json") << QByteArray("{nope");
        QTest::newRow("an array") << QByteArray("[]");
        QTest::newRow("no name") << QByteArray(R"({"Version":"2.1"})");
        QTest::newRow("name of another kind") << QByteArray(R"({"MessageName":12})");
        QTest::newRow("body not an object")
            << QByteArray(R"({"MessageName":"CFX.Heartbeat","MessageBody":3})");
        QTest::newRow("too large") << QByteArray(kMaxRequestBytes + 1, ' ');
    }
    void badRequestsAreRefusedWithAReason() {
        QFETCH(QByteArray, bytes);
        const auto envelope = Envelope::fromBytes(bytes);
        QVERIFY(!envelope.ok());
        QVERIFY(!envelope.error().isEmpty());
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TstCfxEnvelope)

} // namespace tst_cfxenvelope
#include "tst_cfxenvelope.moc"
