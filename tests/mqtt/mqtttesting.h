// Helpers shared by the MQTT tests: settings for a test broker (short keep-alive and back-off so
// tests run in seconds), waiting for a client's state, and running mosquitto_sub / mosquitto_pub
// as independent clients.
#pragma once

#include "mosquittobroker.h"
#include "mqtt/mqttclient.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTest>

// Starts `broker` or skips the test when Mosquitto is not installed.
#define TIPSCOPE_START_BROKER(broker)                                                              \
    do {                                                                                           \
        const QString whyNot = tipscope::testing::MosquittoBroker::skipReason();                   \
        if (!whyNot.isEmpty())                                                                     \
            QSKIP(qPrintable(whyNot));                                                             \
        QString brokerError;                                                                       \
        QVERIFY2((broker).start(&brokerError), qPrintable(brokerError));                           \
    } while (false)

namespace tipscope::testing {

// libmosquitto's smallest keep-alive.
constexpr int kTestKeepAliveSeconds = 5;

inline mqtt::MqttSettings brokerSettings(const MosquittoBroker &broker, const QString &clientId) {
    mqtt::MqttSettings settings;
    settings.host = QStringLiteral("127.0.0.1");
    settings.port = broker.port();
    settings.clientId = clientId;
    settings.keepAliveSeconds = kTestKeepAliveSeconds;
    settings.retryMinMs = 100;
    settings.retryMaxMs = 400;
    return settings;
}

[[nodiscard]] inline bool waitForState(const mqtt::MqttClient &client,
                                       mqtt::MqttClient::State state, int timeoutMs = 10000) {
    return QTest::qWaitFor([&] { return client.state() == state; }, timeoutMs);
}

// Starts the client and waits until it is connected.
[[nodiscard]] inline bool connectClient(mqtt::MqttClient &client,
                                        const mqtt::MqttSettings &settings) {
    client.setSettings(settings);
    client.start();
    return waitForState(client, mqtt::MqttClient::State::Connected);
}

// Starts the client and waits for its first problem (a failed attempt); false if none came.
[[nodiscard]] inline bool startUntilProblem(mqtt::MqttClient &client,
                                            const mqtt::MqttSettings &settings,
                                            int timeoutMs = 10000) {
    QSignalSpy problems(&client, &mqtt::MqttClient::problemOccurred);
    client.setSettings(settings);
    client.start();
    return problems.isValid() && problems.wait(timeoutMs);
}

// Subscribes to `filter` (sent on connecting), connects, and waits until the broker granted it.
[[nodiscard]] inline bool subscribeAndConnect(mqtt::MqttClient &client,
                                              const mqtt::MqttSettings &settings,
                                              const QString &filter) {
    QSignalSpy subscribed(&client, &mqtt::MqttClient::subscribed);
    if (!subscribed.isValid() || !client.subscribe(filter).ok() || !connectClient(client, settings))
        return false;
    return QTest::qWaitFor([&] { return !subscribed.isEmpty(); }, 5000) &&
           subscribed.first().at(1).toBool();
}

// mosquitto_sub or mosquitto_pub against the broker, on 127.0.0.1.
inline void startTool(QProcess &process, const QString &tool, const MosquittoBroker &broker,
                      const QStringList &arguments) {
    process.start(tool, QStringList{QStringLiteral("-h"), QStringLiteral("127.0.0.1"),
                                    QStringLiteral("-p"), QString::number(broker.port())} +
                            arguments);
}

} // namespace tipscope::testing
