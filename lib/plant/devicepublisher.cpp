#include "devicepublisher.h"

#include "model/device/devicemodel.h"
#include "model/device/feedermodel.h"
#include "model/device/stationmodel.h"
#include "mqtt/mqttclient.h"

#include <QDateTime>
#include <QJsonDocument>

namespace tipscope::plant {

using protocol::Group;
using protocol::Role;

namespace {
qint64 nowMs() {
    return QDateTime::currentMSecsSinceEpoch();
}
} // namespace

DevicePublisher::DevicePublisher(mqtt::MqttClient &shared, const AgentConfig &config,
                                 const Publisher &who, model::DeviceModel &device,
                                 DevicePlace place, QObject *parent)
    : QObject(parent)
    , m_shared(shared)
    , m_config(config)
    , m_who(who)
    , m_device(&device)
    , m_place(std::move(place))
    , m_presence(std::make_unique<mqtt::MqttClient>()) {
    mqtt::MqttSettings settings = config.broker;
    settings.clientId = m_place.client;
    settings.cleanSession = true; // it publishes only its status: nothing to keep
    // The will's time is when the device came online, not when it went; "will" says so, so a
    // viewer that first sees it does not take that time for the moment the agent went away.
    QJsonObject will = statusPayload(false, who, nowMs());
    will.insert(QStringLiteral("will"), true);
    settings.will = {m_place.root + QStringLiteral("/status"),
                     QJsonDocument(will).toJson(QJsonDocument::Compact), 1, true};
    m_presence->setSettings(settings);
    // Dozens of presence connections sit idle: unwatched, they cost the lines' wires nothing.
    m_presence->setQuiet(true);
    connect(m_presence.get(), &mqtt::MqttClient::connected, this, &DevicePublisher::publishStatus);
    connect(m_presence.get(), &mqtt::MqttClient::published, this, [this](int id) {
        if (id == m_offlineId && id != 0) {
            m_offlineConfirmed = true;
            Q_EMIT offline();
        }
    });
    connect(&device, &model::DeviceModel::lineUpChanged, this, &DevicePublisher::publishStatus);
    connect(&device, &model::DeviceModel::parameterChanged, this,
            &DevicePublisher::onParameterChanged);
    if (auto *station = qobject_cast<model::StationModel *>(&device)) {
        for (model::PortModel *port : station->ports())
            if (model::Parameter *tip = port->parameter(Role::TipTemperature))
                connect(tip, &model::Parameter::updated, this,
                        [this, n = port->number(), tip] { onReading(n, tip); });
    } else if (auto *feeder = qobject_cast<model::FeederModel *>(&device)) {
        if (model::Parameter *fed = feeder->parameter(Role::FedLength))
            connect(fed, &model::Parameter::updated, this, [this, fed] { onReading(0, fed); });
    }
    m_infoTimer.setSingleShot(true);
    m_infoTimer.setInterval(300);
    connect(&m_infoTimer, &QTimer::timeout, this, &DevicePublisher::publishInfo);
    if (config.live.batchMs > 0) {
        m_batchTimer.setInterval(config.live.batchMs);
        connect(&m_batchTimer, &QTimer::timeout, this, &DevicePublisher::flushBatches);
        m_batchTimer.start();
    }
    m_countersTimer.setInterval(config.countersIntervalS * 1000);
    connect(&m_countersTimer, &QTimer::timeout, this, &DevicePublisher::publishCounters);
    m_countersTimer.start();
    m_presence->start();
    publishRetained();
}

DevicePublisher::~DevicePublisher() = default;

void DevicePublisher::goOffline() {
    flushBatches();
    if (m_presence->state() != mqtt::MqttClient::State::Connected) {
        Q_EMIT offline();
        return;
    }
    m_offlineId = publishOffline();
    if (m_offlineId == 0)
        Q_EMIT offline();
}

int DevicePublisher::publishOffline() {
    const auto sent = m_presence->publish(
        m_place.root + QStringLiteral("/status"),
        QJsonDocument(statusPayload(false, m_who, nowMs())).toJson(QJsonDocument::Compact), 1,
        true);
    return sent.ok() ? sent.messageId : 0;
}

void DevicePublisher::retire(bool sayOffline) {
    flushBatches(); // while the shared client is still there
    // From here on nothing reaches the shared client, which goes before this object does.
    m_device = nullptr;
    m_countersTimer.stop();
    m_infoTimer.stop();
    m_batchTimer.stop();
    if (m_presence->state() != mqtt::MqttClient::State::Connected) {
        deleteLater();
        return;
    }
    if (sayOffline)
        (void)publishOffline();
    connect(m_presence.get(), &mqtt::MqttClient::stateChanged, this,
            [this](mqtt::MqttClient::State state) {
                if (state == mqtt::MqttClient::State::Stopped)
                    deleteLater();
            });
    QTimer::singleShot(5000, this, &QObject::deleteLater); // a broker that never answers
    m_presence->stop();
}

void DevicePublisher::publishRetained() {
    if (m_shared.state() != mqtt::MqttClient::State::Connected || !m_device)
        return;
    publishInfo();
    publishCounters();
    publishAlarms(true);
}

void DevicePublisher::publishStatus() {
    if (!m_device || m_presence->state() != mqtt::MqttClient::State::Connected)
        return;
    (void)m_presence->publish(
        m_place.root + QStringLiteral("/status"),
        QJsonDocument(statusPayload(true, m_who, nowMs(), m_device->isLineUp()))
            .toJson(QJsonDocument::Compact),
        1, true);
}

void DevicePublisher::publishInfo() {
    if (!m_device)
        return;
    publish(QStringLiteral("info"), infoPayload(*m_device, m_place.line, m_place.name, nowMs()), 1,
            true);
}

void DevicePublisher::publishCounters() {
    if (!m_device)
        return;
    publish(QStringLiteral("counters"), countersPayload(*m_device, nowMs()), 1, true);
}

void DevicePublisher::publishAlarms(bool always) {
    const QJsonArray alarms = activeAlarms(*m_device);
    if (!always && m_alarmsPublished && alarms == m_alarms)
        return;
    m_alarms = alarms;
    m_alarmsPublished = m_shared.state() == mqtt::MqttClient::State::Connected;
    publish(QStringLiteral("alarms"), alarmsPayload(alarms, nowMs()), 1, true);
}

void DevicePublisher::onParameterChanged(model::Parameter *p) {
    if (!m_device)
        return;
    const protocol::CommandSpec &meta = p->meta();
    if (meta.group == Group::Errors) {
        publishAlarms(false);
    } else if (meta.role == Role::ConnectedTool) {
        m_infoTimer.start();
    } else if (meta.group == Group::Counter && p->number()) {
        const qint64 value = *p->number();
        const auto before = m_counterValues.constFind(p->code());
        const bool reset = before != m_counterValues.cend() && value < *before;
        m_counterValues.insert(p->code(), value);
        const bool complete = !m_countersComplete &&
                              m_counterValues.size() == m_device->parameters(Group::Counter).size();
        m_countersComplete = m_countersComplete || complete;
        if (reset || complete)
            publishCounters();
    }
}

void DevicePublisher::onReading(int port, model::Parameter *timeSource) {
    if (!m_device)
        return;
    const qint64 readMs = timeSource->lastUpdate().toMSecsSinceEpoch();
    LiveSlot &slot = m_live[port];
    const qint64 interval = m_config.live.intervalMs;
    if (readMs < slot.dueMs)
        return;
    // Keeps the rate on average; after a pause (a lost line) it starts afresh.
    slot.dueMs = readMs - slot.dueMs > interval ? readMs + interval : slot.dueMs + interval;
    QJsonObject payload;
    if (port == 0)
        payload = feederLivePayload(*qobject_cast<model::FeederModel *>(m_device.data()), readMs);
    else
        payload = portLivePayload(*qobject_cast<model::StationModel *>(m_device.data())->port(port),
                                  readMs);
    if (m_config.live.batchMs <= 0)
        return sendLive(port, payload);
    slot.batch.append(payload);
}

void DevicePublisher::flushBatches() {
    for (auto it = m_live.begin(); it != m_live.end(); ++it) {
        if (it->batch.isEmpty())
            continue;
        sendLive(it.key(), {{QStringLiteral("ts"), it->batch.first()[QStringLiteral("ts")]},
                            {QStringLiteral("samples"), it->batch}});
        it->batch = {};
    }
}

void DevicePublisher::sendLive(int port, const QJsonObject &payload) {
    if (!m_device || m_shared.state() != mqtt::MqttClient::State::Connected)
        return; // live values are not kept for later: they are not backfilled
    publish(liveTopic(port), payload, 0, false);
    ++m_liveCount;
}

QString DevicePublisher::liveTopic(int port) const {
    return port == 0 ? QStringLiteral("feeder/live") : QStringLiteral("port/%1/live").arg(port);
}

void DevicePublisher::publish(const QString &leaf, const QJsonObject &payload, int qos,
                              bool retain) {
    if (!m_device || m_shared.state() != mqtt::MqttClient::State::Connected)
        return; // sent again by publishRetained() once connected
    (void)m_shared.publish(m_place.root + QLatin1Char('/') + leaf,
                           QJsonDocument(payload).toJson(QJsonDocument::Compact), qos, retain);
}

} // namespace tipscope::plant
