// MqttClient when things go wrong: a wrong password is reported as such and retried with
// growing waits; a broker that is stopped and started again is found again by itself, with the
// subscriptions renewed; a QoS 1 message in flight when the broker dies is delivered after the
// reconnect; a closed port and an unknown host are reported; stop() ends the retries.
#include "mqtttesting.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_mqttreconnect {

using namespace tipscope::mqtt;
using namespace tipscope::testing;
using State = MqttClient::State;

namespace {

const QString kUser = QStringLiteral("line-7");
const QString kPassword = QStringLiteral("s3cret-Pa55");

BrokerOptions withUser() {
    BrokerOptions options;
    options.users.insert(kUser, kPassword);
    return options;
}

MqttSettings withPassword(const MosquittoBroker &broker, const QByteArray &password) {
    MqttSettings settings = brokerSettings(broker, QStringLiteral("agent"));
    settings.username = kUser;
    settings.password = password;
    return settings;
}

// The waits before each attempt, as the client announced them.
QList<int> retryDelays(MqttClient &client, int attempts) {
    QList<int> delays;
    QObject context;
    QObject::connect(&client, &MqttClient::stateChanged, &context, [&](State state) {
        if (state == State::WaitingToRetry)
            delays << client.retryDelayMs();
    });
    Q_UNUSED(QTest::qWaitFor([&] { return delays.size() >= attempts; }, 10000));
    return delays;
}

} // namespace

class TstMqttReconnect : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void wrongPasswordIsReportedAndRetriedWithGrowingWaits_data();
    void wrongPasswordIsReportedAndRetriedWithGrowingWaits();
    void rightPasswordConnects();
    void clientFindsARestartedBrokerAndItsSubscriptionsAgain();
    void qos1MessageInFlightWhenTheBrokerDiesIsDeliveredAfterReconnecting();
    void closedPortIsReportedAsUnreachable();
    void unknownHostIsReported();
    void stopEndsTheRetries();
};

void TstMqttReconnect::wrongPasswordIsReportedAndRetriedWithGrowingWaits_data() {
    QTest::addColumn<MqttProtocol>("protocol");
    QTest::newRow("MQTT 3.1.1") << MqttProtocol::V311;
    QTest::newRow("MQTT 5") << MqttProtocol::V5;
}

void TstMqttReconnect::wrongPasswordIsReportedAndRetriedWithGrowingWaits() {
    QFETCH(MqttProtocol, protocol);
    MosquittoBroker broker(withUser());
    TIPSCOPE_START_BROKER(broker);
    MqttSettings settings = withPassword(broker, "not-the-password");
    settings.protocol = protocol;
    MqttClient client;
    QSignalSpy problems(&client, &MqttClient::problemOccurred);
    QVERIFY(problems.isValid());
    client.setSettings(settings);
    client.start();

    QCOMPARE(retryDelays(client, 4), (QList<int>{100, 200, 400, 400}));
    QVERIFY(problems.count() >= 4);
    // Mosquitto answers "not authorised" to a wrong password (3.1.1 code 5, MQTT 5 code 135).
    QCOMPARE(problems.first().at(0).value<MqttProblem>(), MqttProblem::NotAuthorised);
    QVERIFY2(client.problemText().contains(QLatin1String("user name or password")),
             qPrintable(client.problemText()));
    QVERIFY(client.state() != State::Connected);
}

void TstMqttReconnect::rightPasswordConnects() {
    MosquittoBroker broker(withUser());
    TIPSCOPE_START_BROKER(broker);
    MqttClient client;
    QVERIFY(connectClient(client, withPassword(broker, kPassword.toUtf8())));
    QCOMPARE(client.problem(), MqttProblem::None);
}

void TstMqttReconnect::clientFindsARestartedBrokerAndItsSubscriptionsAgain() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient subscriber;
    MqttClient publisher;
    QVERIFY(subscribeAndConnect(subscriber, brokerSettings(broker, QStringLiteral("plant-view")),
                                QStringLiteral("tipscope/v1/#")));
    QVERIFY(connectClient(publisher, brokerSettings(broker, QStringLiteral("agent"))));
    QSignalSpy subscribed(&subscriber, &MqttClient::subscribed);
    QSignalSpy received(&subscriber, &MqttClient::messageReceived);
    QSignalSpy lost(&publisher, &MqttClient::disconnected);
    QVERIFY(subscribed.isValid() && received.isValid() && lost.isValid());

    broker.stop();
    QVERIFY(lost.wait(5000));
    QVERIFY(!lost.first().at(0).toString().isEmpty());
    QVERIFY(publisher.state() != State::Connected);
    QVERIFY(!publisher.publish(QStringLiteral("tipscope/v1/x/joint"), "lost", 1, false).ok());

    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error)); // same port, no sessions kept
    QVERIFY(waitForState(publisher, State::Connected));
    QVERIFY(waitForState(subscriber, State::Connected));
    QTRY_VERIFY_WITH_TIMEOUT(subscribed.count() > 0, 5000);
    const MqttResult sent =
        publisher.publish(QStringLiteral("tipscope/v1/x/joint"), "after", 1, false);
    QVERIFY2(sent.ok(), qPrintable(sent.error));
    QVERIFY(received.wait(5000));
    QCOMPARE(received.first().at(1).toByteArray(), QByteArray("after"));
}

void TstMqttReconnect::qos1MessageInFlightWhenTheBrokerDiesIsDeliveredAfterReconnecting() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient publisher;
    QSignalSpy published(&publisher, &MqttClient::published);
    QVERIFY(published.isValid());
    QVERIFY(connectClient(publisher, brokerSettings(broker, QStringLiteral("agent"))));

    broker.freeze();
    const MqttResult sent =
        publisher.publish(QStringLiteral("tipscope/v1/x/joint"), "j1", 1, false);
    QVERIFY(sent.ok());
    broker.kill(); // while frozen: the PUBACK never comes
    QVERIFY(waitForState(publisher, State::WaitingToRetry));
    QCOMPARE(published.count(), 0);
    QCOMPARE(publisher.pendingCount(), 1);

    QProcess sub; // an independent client waits for the message sent again
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));
    startTool(sub, QStringLiteral("mosquitto_sub"), broker,
              {QStringLiteral("-C"), QStringLiteral("1"), QStringLiteral("-W"),
               QStringLiteral("15"), QStringLiteral("-t"), QStringLiteral("tipscope/v1/x/joint")});
    QVERIFY(published.wait(15000));
    QCOMPARE(published.first().at(0).toInt(), sent.messageId);
    QCOMPARE(publisher.pendingCount(), 0);
    Q_UNUSED(sub.waitForFinished(1000)); // it may have subscribed after the message passed
}

void TstMqttReconnect::closedPortIsReportedAsUnreachable() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    const MqttSettings settings = brokerSettings(broker, QStringLiteral("agent"));
    broker.stop();
    MqttClient client;
    QVERIFY(startUntilProblem(client, settings));
    QCOMPARE(client.problem(), MqttProblem::Unreachable);
    QVERIFY2(client.problemText().contains(QString::number(settings.port)),
             qPrintable(client.problemText()));
    QVERIFY(waitForState(client, State::WaitingToRetry));
}

void TstMqttReconnect::unknownHostIsReported() {
    MqttSettings settings;
    settings.host = QStringLiteral("no-such-broker.invalid"); // .invalid never resolves
    MqttClient client;
    QSignalSpy problems(&client, &MqttClient::problemOccurred);
    QVERIFY(problems.isValid());
    client.setSettings(settings);
    client.start();
    QCOMPARE(client.state(), State::Connecting); // the lookup runs on another thread
    QVERIFY(problems.wait(30000));
    QCOMPARE(client.problem(), MqttProblem::HostNotFound);
    QVERIFY(client.problemText().contains(settings.host));
    QCOMPARE(client.state(), State::WaitingToRetry);
}

void TstMqttReconnect::stopEndsTheRetries() {
    MosquittoBroker broker(withUser());
    TIPSCOPE_START_BROKER(broker);
    MqttClient client;
    client.setSettings(withPassword(broker, "wrong"));
    client.start();
    QVERIFY(waitForState(client, State::WaitingToRetry));
    QSignalSpy states(&client, &MqttClient::stateChanged);
    QVERIFY(states.isValid());
    client.stop();
    QCOMPARE(client.state(), State::Stopped);
    QTest::qWait(500); // longer than the longest wait between attempts
    QCOMPARE(states.count(), 1);
}

TIPSCOPE_TEST_GUILESS_MAIN(TstMqttReconnect)

} // namespace tst_mqttreconnect
#include "tst_mqttreconnect.moc"
