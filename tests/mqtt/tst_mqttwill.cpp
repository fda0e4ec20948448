// The last will, as a plant sees presence: a client killed with SIGKILL, or frozen as if its
// network were cut, is announced offline by the broker within 1.5 x keep-alive, seen by
// mosquitto_sub as an independent client; a client destroyed without stop() also leaves its will
// behind, and one that stop()s does not (it publishes its own "offline" first).
#include "mqtttesting.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>
#include <signal.h>

namespace tst_mqttwill {

using namespace tipscope::mqtt;
using namespace tipscope::testing;

namespace {

const QString kStatus = QStringLiteral("tipscope/v1/site/line/01-dme/status");
const QByteArray kOnline = R"({"online": true})";
const QByteArray kOffline = R"({"online": false})";
// 1.5 x keep-alive: the most the broker may wait before it gives up on a silent client. A
// killed client's socket is closed by the kernel, so its will comes at once.
constexpr int kWillDeadlineMs = kTestKeepAliveSeconds * 1500;
// Mosquitto 2.0 looks at keep-alives only every 5 s (its keepalive__check), so a client that
// merely went silent may wait that much longer.
constexpr int kBrokerCheckMs = 6000;

// Reads one line from the process within the time given; empty when none came.
QByteArray readLine(QProcess &process, int timeoutMs) {
    const bool arrived = QTest::qWaitFor(
        [&] { return process.canReadLine() || process.state() == QProcess::NotRunning; },
        timeoutMs);
    return arrived ? process.readLine().trimmed() : QByteArray();
}

} // namespace

class TstMqttWill : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void killedClientIsAnnouncedOfflineByItsWill_data();
    void killedClientIsAnnouncedOfflineByItsWill();
    void destroyedClientLeavesItsWill();
    void stoppedClientLeavesNoWill();
};

void TstMqttWill::killedClientIsAnnouncedOfflineByItsWill_data() {
    QTest::addColumn<int>("signal");
    QTest::addColumn<int>("deadlineMs");
    QTest::newRow("kill -9") << int(SIGKILL) << kWillDeadlineMs;
    QTest::newRow("frozen, as if the network were cut")
        << int(SIGSTOP) << kWillDeadlineMs + kBrokerCheckMs;
}

void TstMqttWill::killedClientIsAnnouncedOfflineByItsWill() {
    QFETCH(int, signal);
    QFETCH(int, deadlineMs);
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    QProcess agent;
    agent.start(QStringLiteral(MQTT_WILL_CLIENT),
                {QString::number(broker.port()), kStatus, QString::number(kTestKeepAliveSeconds)});
    QCOMPARE(readLine(agent, 10000), QByteArray("ready"));

    QProcess sub;
    startTool(sub, QStringLiteral("mosquitto_sub"), broker,
              {QStringLiteral("-C"), QStringLiteral("2"), QStringLiteral("-t"), kStatus});
    QCOMPARE(readLine(sub, 10000), kOnline); // retained: the subscription is in place

    ::kill(pid_t(agent.processId()), signal);
    QCOMPARE(readLine(sub, deadlineMs), kOffline);
    agent.kill(); // a frozen one too
    agent.waitForFinished(5000);
}

void TstMqttWill::destroyedClientLeavesItsWill() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient watcher;
    QSignalSpy received(&watcher, &MqttClient::messageReceived);
    QVERIFY(received.isValid());
    QVERIFY(
        subscribeAndConnect(watcher, brokerSettings(broker, QStringLiteral("watcher")), kStatus));

    MqttSettings settings = brokerSettings(broker, QStringLiteral("agent"));
    settings.will = {kStatus, kOffline, 1, false};
    {
        MqttClient agent;
        QVERIFY(connectClient(agent, settings));
    }
    QVERIFY(received.wait(kWillDeadlineMs));
    QCOMPARE(received.first().at(1).toByteArray(), kOffline);
}

void TstMqttWill::stoppedClientLeavesNoWill() {
    MosquittoBroker broker;
    TIPSCOPE_START_BROKER(broker);
    MqttClient watcher;
    QSignalSpy received(&watcher, &MqttClient::messageReceived);
    QVERIFY(received.isValid());
    QVERIFY(
        subscribeAndConnect(watcher, brokerSettings(broker, QStringLiteral("watcher")), kStatus));

    MqttSettings settings = brokerSettings(broker, QStringLiteral("agent"));
    settings.will = {kStatus, "the will", 1, false};
    MqttClient agent;
    QSignalSpy ended(&agent, &MqttClient::disconnected);
    QVERIFY(ended.isValid());
    QVERIFY(connectClient(agent, settings));
    // What an agent does on SIGTERM: say so itself, then leave.
    QVERIFY(agent.publish(kStatus, kOffline, 1, false).ok());
    agent.stop();
    QCOMPARE(agent.state(), MqttClient::State::Stopped);
    QCOMPARE(ended.count(), 1);
    QCOMPARE(ended.first().at(0).toString(), QString());

    QVERIFY(received.wait(5000));
    QCOMPARE(received.first().at(1).toByteArray(), kOffline);
    QTest::qWait(500);
    QCOMPARE(received.count(), 1); // and no will after it
    QVERIFY2(broker.output().contains(QLatin1String("Client agent disconnected.")),
             qPrintable(broker.output()));
}

TIPSCOPE_TEST_GUILESS_MAIN(TstMqttWill)

} // namespace tst_mqttwill
#include "tst_mqttwill.moc"
