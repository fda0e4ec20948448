// The AMQP 1.0 sender against a real RabbitMQ with its AMQP 1.0 plugin (one node for the whole
// test), read by the independent Python consumer: what arrives is the CFX envelope with the
// SDK's AMQP properties, a message counts only once the broker accepted it, and every wrong
// setting gets one clear problem while the sender keeps trying. The node also listens with TLS,
// asking for a client certificate: the sender connects with the right CA and its certificate,
// and is refused, saying what to check, with another CA, without a certificate, or by an address
// the broker's certificate does not name.
#include "cfx/amqpsender.h"
#include "cfx/cfxmessages.h"
#include "cfxtesting.h"
#include "testcertificates.h"
#include "testmain.h"

#include <QJsonArray>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTest>

namespace tst_amqpsender {

using namespace tipscope;
using namespace tipscope::cfx;
using tipscope::testing::CfxConsumer;
using tipscope::testing::RabbitMqBroker;
using tipscope::testing::TestCertificates;

class TstAmqpSender : public QObject {
    Q_OBJECT

    std::unique_ptr<RabbitMqBroker> m_broker;
    TestCertificates m_certificates;
    QString m_noTls; // why the TLS listener is not there

    static bool connect(AmqpSender &sender) {
        return QTest::qWaitFor([&] { return sender.state() == AmqpSender::State::Connected; },
                               20000);
    }

private Q_SLOTS:
    void initTestCase() {
        m_noTls = TestCertificates::skipReason();
        QString error;
        if (m_noTls.isEmpty() && !m_certificates.generate(&error))
            QFAIL(qPrintable(error));
        if (!m_noTls.isEmpty()) {
            testing::startCfxBroker(m_broker);
            return;
        }
        testing::startCfxBroker(m_broker, RabbitMqBroker::Tls{m_certificates.caFile(),
                                                              m_certificates.serverCertificate(),
                                                              m_certificates.serverKey(), true});
    }
    void cleanupTestCase() { m_broker.reset(); }

    void messagesArriveAsCfxWithTheSdkProperties() {
        CfxConsumer consumer;
        QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), 3),
                 qPrintable(consumer.output()));
        AmqpSender sender;
        QSignalSpy accepted(&sender, &AmqpSender::accepted);
        QVERIFY(accepted.isValid());
        sender.start(
            testing::quickSenderSettings(*m_broker, QStringLiteral("/exchange/amq.topic")));
        QVERIFY(connect(sender));
        const QString handle =
            endpointHandle(QStringLiteral("JBC"), QStringLiteral("DDE"), QStringLiteral("L1-1"));
        const Envelope hello = envelopeOf(endpointConnected(handle, QString(), QString()), handle);
        const Envelope beat = envelopeOf(heartbeat(handle, 60000, QJsonArray()), handle);
        const Envelope state = envelopeOf(
            stationStateChanged(StationCondition::InStand, 1000, StationCondition::Working, {}),
            handle);
        QList<quint64> tags{sender.send(toAmqpMessage(hello, Codec::Raw)),
                            sender.send(toAmqpMessage(beat, Codec::Gzip)),
                            sender.send(toAmqpMessage(state, Codec::Raw))};
        QVERIFY(!tags.contains(0));
        QTRY_COMPARE_WITH_TIMEOUT(accepted.size(), 3, 20000);
        QCOMPARE(accepted.at(0).at(0).toULongLong(), tags.at(0));
        QVERIFY2(consumer.finish(), qPrintable(consumer.output()));
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        QCOMPARE(consumer.messages().size(), 3);
        const QJsonObject second = consumer.messages().at(1);
        QCOMPARE(second.value(QStringLiteral("encoding")).toString(), QStringLiteral("gzip"));
        QCOMPARE(second.value(QStringLiteral("subject")).toString(),
                 QStringLiteral("JBC.DDE.L1-1.CFX.Heartbeat"));
        const QJsonObject envelope = second.value(QStringLiteral("envelope")).toObject();
        QCOMPARE(envelope.value(QStringLiteral("UniqueID")).toString(),
                 beat.uniqueId.toString(QUuid::WithoutBraces));
        QCOMPARE(envelope.value(QStringLiteral("MessageBody"))
                     .toObject()
                     .value(QStringLiteral("HeartbeatFrequency"))
                     .toString(),
                 QStringLiteral("00:01:00"));
        QCOMPARE(consumer.messages()
                     .at(2)
                     .value(QStringLiteral("envelope"))
                     .toObject()
                     .value(QStringLiteral("MessageBody"))
                     .toObject()
                     .value(QStringLiteral("NewState"))
                     .toString(),
                 QStringLiteral("1100"));
    }

    void problemsSayWhatToFix_data() {
        QTest::addColumn<QString>("address");
        QTest::addColumn<QByteArray>("password");
        QTest::addColumn<bool>("noBroker");
        QTest::addColumn<QString>("words");
        QTest::newRow("no such exchange")
            << QStringLiteral("/exchange/tipscope-missing") << QByteArray("guest") << false
            << QStringLiteral("does not exist");
        QTest::newRow("refused login")
            << QStringLiteral("/exchange/amq.topic") << QByteArray("wrong") << false
            << QStringLiteral("refused the login");
        QTest::newRow("nothing listening")
            << QStringLiteral("/exchange/amq.topic") << QByteArray("guest") << true
            << QStringLiteral("Nothing accepts connections");
    }
    void problemsSayWhatToFix() {
        QFETCH(QString, address);
        QFETCH(QByteArray, password);
        QFETCH(bool, noBroker);
        QFETCH(QString, words);
        AmqpSender sender;
        QSignalSpy problems(&sender, &AmqpSender::problem);
        QVERIFY(problems.isValid());
        AmqpSender::Settings s = testing::quickSenderSettings(*m_broker, address);
        s.user = QStringLiteral("guest");
        s.password = password;
        if (noBroker) {
            QTcpServer closed; // a port that was free a moment ago
            QVERIFY(closed.listen(QHostAddress::LocalHost));
            s.port = closed.serverPort();
        }
        sender.start(s);
        QTRY_VERIFY_WITH_TIMEOUT(problems.size() >= 2, 20000); // said, and tried again
        const QString text = problems.at(0).at(0).toString();
        QVERIFY2(text.contains(words), qPrintable(text));
        QVERIFY2(!text.contains(QLatin1String("guest")) || password != "guest", qPrintable(text));
        QVERIFY(sender.state() != AmqpSender::State::Connected);
        QCOMPARE(sender.send(AmqpMessage()), quint64(0));
    }

    void tlsChecksBothEnds_data() {
        QTest::addColumn<QString>("host");
        QTest::addColumn<bool>("otherCa");
        QTest::addColumn<bool>("clientCertificate");
        QTest::addColumn<bool>("connects");
        QTest::newRow("its CA and a client certificate")
            << QStringLiteral("localhost") << false << true << true;
        QTest::newRow("another CA") << QStringLiteral("localhost") << true << true << false;
        QTest::newRow("no client certificate")
            << QStringLiteral("localhost") << false << false << false;
        // The broker's certificate names localhost only.
        QTest::newRow("an address the certificate does not name")
            << QStringLiteral("127.0.0.1") << false << true << false;
    }
    void tlsChecksBothEnds() {
        if (!m_noTls.isEmpty())
            QSKIP(qPrintable(m_noTls));
        QFETCH(QString, host);
        QFETCH(bool, otherCa);
        QFETCH(bool, clientCertificate);
        QFETCH(bool, connects);
        AmqpSender sender;
        QSignalSpy problems(&sender, &AmqpSender::problem);
        QSignalSpy accepted(&sender, &AmqpSender::accepted);
        AmqpSender::Settings s =
            testing::quickSenderSettings(*m_broker, QStringLiteral("/exchange/amq.topic"));
        s.host = host;
        s.port = m_broker->tlsPort();
        s.tls = true;
        s.caFile = otherCa ? m_certificates.otherCaFile() : m_certificates.caFile();
        if (clientCertificate) {
            s.certFile = m_certificates.clientCertificate();
            s.keyFile = m_certificates.clientKey();
        }
        sender.start(s);
        QCOMPARE(sender.where(), QStringLiteral("amqps://%1:%2").arg(host).arg(s.port));
        if (connects) {
            QVERIFY2(connect(sender),
                     qPrintable(problems.isEmpty() ? QStringLiteral("no problem said")
                                                   : problems.at(0).at(0).toString()));
            const QString handle = QStringLiteral("JBC.DDE.L1-2");
            const quint64 tag = sender.send(
                toAmqpMessage(envelopeOf(endpointShuttingDown(handle), handle), Codec::Raw));
            QTRY_COMPARE_WITH_TIMEOUT(accepted.size(), 1, 20000);
            QCOMPARE(accepted.at(0).at(0).toULongLong(), tag);
            return;
        }
        QTRY_VERIFY_WITH_TIMEOUT(problems.size() >= 1, 20000);
        const QString text = problems.at(0).at(0).toString();
        QVERIFY2(text.contains(QLatin1String("TLS failed")), qPrintable(text));
        QVERIFY(sender.state() != AmqpSender::State::Connected);
    }

    void aBrokerOutageEndsInAReconnection() {
        AmqpSender sender;
        QSignalSpy lost(&sender, &AmqpSender::disconnected);
        QSignalSpy accepted(&sender, &AmqpSender::accepted);
        sender.start(
            testing::quickSenderSettings(*m_broker, QStringLiteral("/exchange/amq.topic")));
        QVERIFY(connect(sender));
        QString error;
        QVERIFY2(m_broker->pause(&error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(lost.size(), 1, 20000);
        QCOMPARE(sender.send(AmqpMessage()), quint64(0));
        QVERIFY2(m_broker->resume(&error), qPrintable(error));
        QVERIFY(connect(sender));
        const QString handle = QStringLiteral("JBC.DDE.L1-2");
        const quint64 tag = sender.send(
            toAmqpMessage(envelopeOf(endpointShuttingDown(handle), handle), Codec::Raw));
        QTRY_COMPARE_WITH_TIMEOUT(accepted.size(), 1, 20000);
        QCOMPARE(accepted.at(0).at(0).toULongLong(), tag);
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TstAmqpSender)

} // namespace tst_amqpsender
#include "tst_amqpsender.moc"
