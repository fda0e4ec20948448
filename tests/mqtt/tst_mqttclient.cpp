// MqttClient against a real broker: a message goes from one client to another, QoS 1 is
// reported published on the broker's PUBACK, retained messages reach late subscribers (our own
// and mosquitto_sub), mosquitto_pub's messages reach our subscriber, and publishing is refused
// and counted while disconnected or once too many messages wait. A quiet client (a device's
// presence) is watched only around what it sends and still hears its broker go.
#include "mqtt/mqttpump.h"
#include "mqtttesting.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_mqttclient {

using namespace tipscope::mqtt;
using namespace tipscope::testing;

class TstMqttClient : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void messageFromOneClientReachesAnotherThatSubscribed_data();
    void messageFromOneClientReachesAnotherThatSubscribed();
    void messageTheBrokerRefusesIsRejectedWithMqtt5_data();
    void messageTheBrokerRefusesIsRejectedWithMqtt5();
    void qos1MessageIsPublishedOnlyWhenTheBrokerAcknowledges();
    void retainedMessageReachesLateSubscribers();
    void messageFromMosquittoPubReachesOurSubscriber();
    void publishingIsRefusedAndCountedWhileNotConnected();
    void publishingIsRefusedOnceTooManyMessagesWait();
    void invalidTopicsAndFiltersAreRefused();
    void aQuietClientIsWatchedOnlyAroundWhatItSends();
    void aQuietClientHearsItsBrokerGo();
    void aQuietClientReadsAnAcknowledgementThatCameLate();
};

void TstMqttClient::messageFromOneClientReachesAnotherThatSubscribed_data() {
    QTest::addColumn<MqttProtocol>("protocol");
    QTest::newRow("MQTT 3.1.1") << MqttProtocol::V311;
    QTest::newRow("MQTT 5") << MqttProtocol::V5;
}

void TstMqttClient::messageFromOneClientReachesAnotherThatSubscribed() {
    QFETCH(MqttProtocol, protocol);
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttSettings settings = brokerSettings(broker, QStringLiteral("subscriber"));
    settings.protocol = protocol;
    MqttClient subscriber;
    QSignalSpy received(&subscriber, &MqttClient::messageReceived);
    QVERIFY(received.isValid());
    // Subscribed before connecting: sent once connected.
    QVERIFY(subscribeAndConnect(subscriber, settings, QStringLiteral("tipscope/test/#")));

    MqttClient publisher;
    settings.clientId = QStringLiteral("publisher");
    QVERIFY(connectClient(publisher, settings));
    const MqttResult sent = publisher.publish(QStringLiteral("tipscope/test/a"), "hello", 1, false);
    QVERIFY2(sent.ok(), qPrintable(sent.error));
    QVERIFY(received.wait(5000));
    QCOMPARE(received.first().at(0).toString(), QStringLiteral("tipscope/test/a"));
    QCOMPARE(received.first().at(1).toByteArray(), QByteArray("hello"));
    QCOMPARE(received.first().at(2).toBool(), false);
}

void TstMqttClient::messageTheBrokerRefusesIsRejectedWithMqtt5_data() {
    QTest::addColumn<MqttProtocol>("protocol");
    QTest::addColumn<bool>("rejected");
    // MQTT 3.1.1 has no way to say no: the broker acknowledges and drops the message.
    QTest::newRow("MQTT 3.1.1") << MqttProtocol::V311 << false;
    QTest::newRow("MQTT 5") << MqttProtocol::V5 << true;
}

void TstMqttClient::messageTheBrokerRefusesIsRejectedWithMqtt5() {
    QFETCH(MqttProtocol, protocol);
    QFETCH(bool, rejected);
    BrokerOptions options;
    options.acl = QStringLiteral("topic readwrite tipscope/v1/#\n");
    MosquittoBroker broker(options);
    TIPSCOPE_START_BROKER(broker);
    MqttSettings settings = brokerSettings(broker, QStringLiteral("agent"));
    settings.protocol = protocol;
    MqttClient client;
    QSignalSpy published(&client, &MqttClient::published);
    QSignalSpy refused(&client, &MqttClient::publishRejected);
    QVERIFY(published.isValid() && refused.isValid());
    QVERIFY(connectClient(client, settings));

    const MqttResult sent = client.publish(QStringLiteral("elsewhere/joint"), "j", 1, false);
    QVERIFY(sent.ok());
    QTRY_COMPARE_WITH_TIMEOUT(published.count() + refused.count(), 1, 5000);
    QCOMPARE(refused.count(), rejected ? 1 : 0);
    if (rejected) {
        QCOMPARE(refused.first().at(0).toInt(), sent.messageId);
        QVERIFY2(refused.first().at(1).toString().contains(QLatin1String("authori")),
                 qPrintable(refused.first().at(1).toString()));
    }
    QCOMPARE(client.pendingCount(), 0);
}

void TstMqttClient::qos1MessageIsPublishedOnlyWhenTheBrokerAcknowledges() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient client;
    QVERIFY(connectClient(client, brokerSettings(broker, QStringLiteral("publisher"))));
    QSignalSpy published(&client, &MqttClient::published);
    QVERIFY(published.isValid());

    broker.freeze(); // the message reaches the socket, but no PUBACK comes back
    const MqttResult sent = client.publish(QStringLiteral("tipscope/test/q1"), "joint", 1, false);
    QVERIFY2(sent.ok(), qPrintable(sent.error));
    QVERIFY(sent.messageId > 0);
    QTest::qWait(300);
    QCOMPARE(published.count(), 0);
    QCOMPARE(client.pendingCount(), 1);

    broker.thaw();
    QVERIFY(published.wait(5000));
    QCOMPARE(published.first().at(0).toInt(), sent.messageId);
    QCOMPARE(client.pendingCount(), 0);
}

void TstMqttClient::retainedMessageReachesLateSubscribers() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    const QString topic = QStringLiteral("tipscope/v1/site/line/01-dme/status");
    MqttClient publisher;
    QVERIFY(connectClient(publisher, brokerSettings(broker, QStringLiteral("agent"))));
    QSignalSpy published(&publisher, &MqttClient::published);
    QVERIFY(published.isValid());
    QVERIFY(publisher.publish(topic, R"({"online": true})", 1, true).ok());
    QVERIFY(published.wait(5000));

    QProcess sub;
    startTool(sub, QStringLiteral("mosquitto_sub"), broker,
              {QStringLiteral("-C"), QStringLiteral("1"), QStringLiteral("-W"),
               QStringLiteral("10"), QStringLiteral("-v"), QStringLiteral("-t"), topic});
    QVERIFY(sub.waitForFinished(15000));
    QCOMPARE(sub.exitCode(), 0);
    QCOMPARE(sub.readAllStandardOutput().trimmed(), (topic + R"( {"online": true})").toUtf8());

    MqttClient late;
    QSignalSpy received(&late, &MqttClient::messageReceived);
    QVERIFY(received.isValid());
    QVERIFY(late.subscribe(QStringLiteral("tipscope/v1/#")).ok());
    QVERIFY(connectClient(late, brokerSettings(broker, QStringLiteral("plant-view"))));
    QVERIFY(received.wait(5000));
    QCOMPARE(received.first().at(0).toString(), topic);
    QCOMPARE(received.first().at(2).toBool(), true);
}

void TstMqttClient::messageFromMosquittoPubReachesOurSubscriber() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient subscriber;
    QSignalSpy received(&subscriber, &MqttClient::messageReceived);
    QVERIFY(received.isValid());
    QVERIFY(subscribeAndConnect(subscriber, brokerSettings(broker, QStringLiteral("subscriber")),
                                QStringLiteral("tipscope/v1/+/+/+/joint")));

    QProcess pub;
    startTool(pub, QStringLiteral("mosquitto_pub"), broker,
              {QStringLiteral("-q"), QStringLiteral("1"), QStringLiteral("-t"),
               QStringLiteral("tipscope/v1/site/l1/01-dme/joint"), QStringLiteral("-m"),
               QStringLiteral("{\"id\": 7}")});
    QVERIFY(pub.waitForFinished(10000));
    QCOMPARE(pub.exitCode(), 0);
    QVERIFY(received.wait(5000));
    QCOMPARE(received.first().at(0).toString(), QStringLiteral("tipscope/v1/site/l1/01-dme/joint"));
    QCOMPARE(received.first().at(1).toByteArray(), QByteArray("{\"id\": 7}"));
}

void TstMqttClient::publishingIsRefusedAndCountedWhileNotConnected() {
    MqttClient client;
    for (const int qos : {0, 1}) {
        const MqttResult sent = client.publish(QStringLiteral("tipscope/test"), "x", qos, false);
        QVERIFY(!sent.ok());
        QVERIFY2(sent.error.contains(QLatin1String("Not connected")), qPrintable(sent.error));
    }
    QCOMPARE(client.refusedCount(), 2);
    QCOMPARE(client.pendingCount(), 0);
}

void TstMqttClient::publishingIsRefusedOnceTooManyMessagesWait() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttSettings settings = brokerSettings(broker, QStringLiteral("publisher"));
    settings.maxPendingMessages = 3;
    MqttClient client;
    QVERIFY(connectClient(client, settings));
    QSignalSpy published(&client, &MqttClient::published);
    QVERIFY(published.isValid());

    broker.freeze();
    for (int i = 0; i < 3; ++i)
        QVERIFY(client.publish(QStringLiteral("tipscope/test/q1"), "joint", 1, false).ok());
    const MqttResult fourth = client.publish(QStringLiteral("tipscope/test/q1"), "joint", 1, false);
    QVERIFY(!fourth.ok());
    QVERIFY2(fourth.error.contains(QLatin1String("3 messages wait")), qPrintable(fourth.error));
    QCOMPARE(client.refusedCount(), 1);

    broker.thaw();
    QTRY_COMPARE_WITH_TIMEOUT(published.count(), 3, 5000);
    QCOMPARE(client.pendingCount(), 0);
    QVERIFY(client.publish(QStringLiteral("tipscope/test/q1"), "joint", 1, false).ok());
}

void TstMqttClient::invalidTopicsAndFiltersAreRefused() {
    MqttClient client;
    const auto refusal = [&](const QString &topic, int qos) {
        return client.publish(topic, "x", qos, false).error;
    };
    QVERIFY(refusal(QStringLiteral("tipscope/+/status"), 0).contains(QLatin1String("not a topic")));
    QVERIFY(refusal(QString(), 0).contains(QLatin1String("not a topic")));
    QVERIFY(refusal(QStringLiteral("tipscope/status"), 3).contains(QLatin1String("QoS 3")));
    QVERIFY(!client.subscribe(QStringLiteral("tipscope/#/status")).ok());
    QVERIFY(!client.unsubscribe(QStringLiteral("never/subscribed")).ok());
}

TIPSCOPE_TEST_GUILESS_MAIN(TstMqttClient)

void TstMqttClient::aQuietClientIsWatchedOnlyAroundWhatItSends() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient subscriber;
    QSignalSpy received(&subscriber, &MqttClient::messageReceived);
    QVERIFY(subscribeAndConnect(subscriber, brokerSettings(broker, QStringLiteral("subscriber")),
                                QStringLiteral("tipscope/test/#")));
    MqttClient quiet;
    quiet.setQuiet(true);
    QSignalSpy published(&quiet, &MqttClient::published);
    QVERIFY(connectClient(quiet, brokerSettings(broker, QStringLiteral("quiet"))));
    // Idle, it is let go of after at most kQuietAfterTicks ticks and a tick's lateness.
    QTRY_VERIFY_WITH_TIMEOUT(!quiet.watchesReads(), (MqttPump::kQuietAfterTicks + 2) * 1000);

    for (int i = 0; i < 2; ++i) {
        const MqttResult sent =
            quiet.publish(QStringLiteral("tipscope/test/status"), "online", 1, true);
        QVERIFY2(sent.ok(), qPrintable(sent.error));
        QVERIFY(quiet.watchesReads()); // the broker's acknowledgement is on its way
        QTRY_COMPARE_WITH_TIMEOUT(published.size(), i + 1, 1000); // read at once, not on a tick
        QTRY_COMPARE_WITH_TIMEOUT(received.size(), i + 1, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!quiet.watchesReads(), (MqttPump::kQuietAfterTicks + 2) * 1000);
    }
    QCOMPARE(quiet.state(), MqttClient::State::Connected);
    // Its keep-alive comes and goes unwatched: a ping goes out after kTestKeepAliveSeconds of
    // silence, and an answer not read within as long again would end the connection. The
    // answer is read on a tick.
    QTest::qWait(2 * kTestKeepAliveSeconds * 1000 + 1000);
    QCOMPARE(quiet.state(), MqttClient::State::Connected);
}

void TstMqttClient::aQuietClientHearsItsBrokerGo() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient quiet;
    quiet.setQuiet(true);
    QVERIFY(connectClient(quiet, brokerSettings(broker, QStringLiteral("quiet"))));
    QTRY_VERIFY_WITH_TIMEOUT(!quiet.watchesReads(), (MqttPump::kQuietAfterTicks + 2) * 1000);
    QSignalSpy lost(&quiet, &MqttClient::disconnected);
    broker.stop();
    QVERIFY(lost.wait(3000)); // within a tick or two
    QVERIFY(!lost.first().at(0).toString().isEmpty());
}

void TstMqttClient::aQuietClientReadsAnAcknowledgementThatCameLate() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient quiet;
    quiet.setQuiet(true);
    QSignalSpy published(&quiet, &MqttClient::published);
    QVERIFY(connectClient(quiet, brokerSettings(broker, QStringLiteral("quiet"))));
    broker.freeze(); // a broker too busy to answer for a while
    QVERIFY(quiet.publish(QStringLiteral("tipscope/test/status"), "online", 1, true).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!quiet.watchesReads(), (MqttPump::kQuietAfterTicks + 2) * 1000);
    QVERIFY(published.isEmpty());
    broker.thaw();
    // Unwatched, the acknowledgement is read on the next tick.
    QTRY_COMPARE_WITH_TIMEOUT(published.size(), 1, 2500);
    QCOMPARE(quiet.state(), MqttClient::State::Connected);
}

} // namespace tst_mqttclient
#include "tst_mqttclient.moc"
