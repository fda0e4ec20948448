#include "plantsubscriber.h"

#include "benchsupport.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>

namespace tipscope::bench {

namespace {

// The device's root of a topic ("tipscope/v1/site/line/device") and what follows it.
struct TopicParts {
    QString root;
    QString rest;
};

TopicParts split(const QString &topic) {
    constexpr int kRootLevels = 5;
    const qsizetype cut = topic.section(QLatin1Char('/'), 0, kRootLevels - 1).size();
    return {topic.left(cut), topic.mid(cut + 1)};
}

} // namespace

PlantSubscriber::PlantSubscriber(QObject *parent)
    : QObject(parent) {
    connect(&m_client, &mqtt::MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload, bool) {
                onMessage(topic, payload);
            });
}

bool PlantSubscriber::connectTo(int brokerPort, QString *error) {
    mqtt::MqttSettings settings;
    settings.host = QStringLiteral("127.0.0.1");
    settings.port = brokerPort;
    settings.clientId = QStringLiteral("plant-bench-subscriber");
    settings.cleanSession = false;
    settings.keepAliveSeconds = 5;
    // Back at once when the broker returns, so the drain measured is the agent's, not ours.
    settings.retryMinMs = 100;
    settings.retryMaxMs = 400;
    connect(&m_client, &mqtt::MqttClient::subscribed, this,
            [this](int, bool ok) { m_granted = ok; });
    if (const mqtt::MqttResult subscribing = m_client.subscribe(QStringLiteral("tipscope/v1/#"));
        !subscribing.ok()) {
        *error = QStringLiteral("the subscription was refused: ") + subscribing.error;
        return false;
    }
    m_client.setSettings(settings);
    m_client.start();
    if (!runUntil([&] { return m_granted; }, 10000)) {
        *error = QStringLiteral("the subscriber did not connect: ") + m_client.problemText();
        return false;
    }
    return true;
}

void PlantSubscriber::startMeasuring() {
    m_measuring = true;
    m_measuredMessages = 0;
    m_measuredLive = 0;
    m_liveLatenciesMs.clear();
}

int PlantSubscriber::onlineDevices() const {
    return int(std::count(m_online.cbegin(), m_online.cend(), true));
}

int PlantSubscriber::ports() const {
    int sum = 0;
    for (const int n : m_ports)
        sum += n;
    return sum;
}

void PlantSubscriber::onMessage(const QString &topic, const QByteArray &payload) {
    const qint64 nowMs = QDateTime::currentMSecsSinceEpoch();
    const QJsonObject json = QJsonDocument::fromJson(payload).object();
    const TopicParts parts = split(topic);
    if (m_measuring)
        ++m_measuredMessages;
    if (parts.rest == QLatin1String("status")) {
        m_online.insert(parts.root, json.value(QStringLiteral("online")).toBool());
    } else if (parts.rest == QLatin1String("info")) {
        m_ports.insert(parts.root, int(json.value(QStringLiteral("ports")).toArray().size()));
    } else if (parts.rest == QLatin1String("joint")) {
        m_joints[json.value(QStringLiteral("id")).toString()].append(nowMs);
    } else if (m_measuring && parts.rest.startsWith(QLatin1String("port/")) &&
               parts.rest.endsWith(QLatin1String("/live"))) {
        ++m_measuredLive;
        const QDateTime read =
            QDateTime::fromString(json.value(QStringLiteral("ts")).toString(), Qt::ISODateWithMs);
        if (read.isValid())
            m_liveLatenciesMs.append(double(nowMs - read.toMSecsSinceEpoch()));
    }
}

} // namespace tipscope::bench
