// PlantSubscriber: the plant's side of `tipscope-bench plant`, what a dashboard or MES would be.
// One MqttClient with a persistent session (a fixed client id, clean session off) and a QoS 1
// subscription to tipscope/v1/#, so a broker that restarts with persistence hands over the QoS 1
// messages published while the subscriber was reconnecting, as a plant's subscriber gets them.
//
// It keeps what the bench measures, stamped when each message is handed to it: every message
// counted; the devices whose retained status says online; the ports each device's info lists;
// while measuring (startMeasuring()), the messages and the latency of each `port/<n>/live` (its
// arrival minus its payload's "ts", the time the agent read the value); and for the whole run
// every joint's id with the arrival time of each copy.
#pragma once

#include "mqtt/mqttclient.h"

#include <QHash>
#include <QList>
#include <QObject>

namespace tipscope::bench {

class PlantSubscriber : public QObject {
    Q_OBJECT
public:
    explicit PlantSubscriber(QObject *parent = nullptr);

    // Subscribes and connects to the broker; false with *error when it did not within 10 s.
    [[nodiscard]] bool connectTo(int brokerPort, QString *error);

    // Starts the measuring window: the message and live counts and the latencies start anew.
    void startMeasuring();
    [[nodiscard]] qint64 measuredMessages() const { return m_measuredMessages; }
    [[nodiscard]] qint64 measuredLive() const { return m_measuredLive; }
    // One a live message whose "ts" could be read.
    [[nodiscard]] const QList<double> &liveLatenciesMs() const { return m_liveLatenciesMs; }

    // Devices (topic roots) whose last status said online.
    [[nodiscard]] int onlineDevices() const;
    // The ports of every device's last info, summed.
    [[nodiscard]] int ports() const;
    // Each joint id received, with the arrival time (ms since the epoch) of every copy.
    [[nodiscard]] const QHash<QString, QList<qint64>> &jointArrivals() const { return m_joints; }

private:
    void onMessage(const QString &topic, const QByteArray &payload);

    mqtt::MqttClient m_client;
    QHash<QString, bool> m_online;
    QHash<QString, int> m_ports;
    QHash<QString, QList<qint64>> m_joints;
    bool m_granted = false;
    bool m_measuring = false;
    qint64 m_measuredMessages = 0;
    qint64 m_measuredLive = 0;
    QList<double> m_liveLatenciesMs;
};

} // namespace tipscope::bench
