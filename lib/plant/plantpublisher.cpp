#include "plantpublisher.h"

#include "planttopics.h"

#include "journal/journal.h"
#include "model/workspace/workspace.h"
#include "mqtt/mqttclient.h"
#include "mqtt/mqtttopic.h"

#include <QSysInfo>

namespace tipscope::plant {

PlantPublisher::PlantPublisher(model::Workspace &workspace, journal::Journal &journal,
                               QObject *parent)
    : QObject(parent)
    , m_workspace(workspace)
    , m_journal(journal) {
    m_stopTimer.setSingleShot(true);
    connect(&m_stopTimer, &QTimer::timeout, this, &PlantPublisher::finishStop);
    connect(&workspace, &model::Workspace::linesChanged, this, &PlantPublisher::syncAll);
    connect(&workspace, &model::Workspace::lineDevicesChanged, this, &PlantPublisher::syncLine);
}

PlantPublisher::~PlantPublisher() = default;

void PlantPublisher::start(const AgentConfig &config, const Publisher &who) {
    m_stopTimer.stop();
    // The devices hand over to their successors; under the same roots without going offline.
    const bool sameRoots = m_client && config.site == m_config.site;
    for (auto &device : m_devices) {
        DevicePublisher *old = device.release();
        old->setParent(this);
        old->retire(!sameRoots);
    }
    m_devices.clear();
    m_remoteApply.reset();
    m_forwarder.reset();
    if (m_client)
        m_client->stop();
    m_client.reset();
    m_config = config;
    m_who = who;
    m_agentId =
        config.broker.clientId.isEmpty()
            ? mqtt::sanitizeTopicLevel(
                  QStringLiteral("tipscope-%1-%2").arg(QSysInfo::machineHostName(), config.site))
            : config.broker.clientId;
    mqtt::MqttSettings settings = config.broker;
    settings.clientId = m_agentId; // stable, so the broker keeps the session across restarts
    m_client = std::make_unique<mqtt::MqttClient>();
    m_client->setSettings(settings);
    connect(m_client.get(), &mqtt::MqttClient::connected, this, [this] {
        for (const auto &device : m_devices)
            device->publishRetained();
    });
    m_forwarder = std::make_unique<JournalForwarder>(
        m_journal, *m_client, [this](const model::DeviceIdentity &d) { return placeOf(d); });
    m_remoteApply =
        std::make_unique<RemoteApply>(*m_client, m_journal, config.site, config.remoteApply,
                                      [this](const QString &root) -> model::DeviceModel * {
                                          for (const auto &device : m_devices)
                                              if (device->place().root == root)
                                                  return device->device();
                                          return nullptr;
                                      });
    m_client->start();
    syncAll();
}

void PlantPublisher::stop(int stopTimeoutMs) {
    if (!m_client)
        return Q_EMIT stopped();
    m_awaitingOffline = int(m_devices.size());
    for (const auto &device : m_devices)
        device->goOffline(); // each answers with offline(), perhaps at once
    if (m_awaitingOffline > 0)
        m_stopTimer.start(stopTimeoutMs);
    else
        finishStop();
}

void PlantPublisher::onOffline() {
    if (m_awaitingOffline > 0 && --m_awaitingOffline == 0 && m_stopTimer.isActive()) {
        m_stopTimer.stop();
        finishStop();
    }
}

void PlantPublisher::finishStop() {
    // A device whose offline status the broker did not confirm keeps its connection until the
    // publisher goes: closed without DISCONNECT, the broker then publishes its will (offline).
    for (const auto &device : m_devices)
        if (device->isOfflineConfirmed())
            device->presence().stop();
    if (m_client)
        m_client->stop();
    Q_EMIT stopped();
}

void PlantPublisher::syncAll() {
    if (!m_client)
        return;
    // Devices whose session is gone (a workspace opened anew) have gone with it.
    const auto gone = std::remove_if(m_devices.begin(), m_devices.end(),
                                     [](const auto &d) { return d->device() == nullptr; });
    const bool changed = gone != m_devices.end();
    m_devices.erase(gone, m_devices.end());
    for (int i = 0; i < m_workspace.count(); ++i)
        syncLine(i);
    if (changed)
        Q_EMIT devicesChanged();
}

void PlantPublisher::syncLine(int index) {
    if (!m_client || index >= m_workspace.count())
        return;
    const QList<model::DeviceModel *> &now = m_workspace.session(index)->devices();
    const QString line = m_workspace.line(index).name;
    bool changed = false;
    for (auto it = m_devices.begin(); it != m_devices.end();) {
        model::DeviceModel *device = (*it)->device();
        if ((*it)->place().line == line && (!device || !now.contains(device))) {
            // Its presence client closes without DISCONNECT: the broker publishes its will.
            it = m_devices.erase(it);
            changed = true;
        } else {
            ++it;
        }
    }
    for (model::DeviceModel *device : now) {
        const bool known = std::any_of(m_devices.begin(), m_devices.end(),
                                       [device](const auto &d) { return d->device() == device; });
        if (!known) {
            addDevice(index, *device);
            changed = true;
        }
    }
    if (changed)
        Q_EMIT devicesChanged();
}

void PlantPublisher::addDevice(int index, model::DeviceModel &device) {
    const model::WorkspaceLine &line = m_workspace.line(index);
    auto publisher = std::make_unique<DevicePublisher>(
        *m_client, m_config, m_who, device,
        devicePlace(m_config.site, m_agentId, line.name, line.deviceName(device.address()),
                    device.address(), device.family()));
    connect(publisher.get(), &DevicePublisher::offline, this, &PlantPublisher::onOffline);
    m_devices.push_back(std::move(publisher));
}

DevicePlace PlantPublisher::placeOf(const model::DeviceIdentity &identity) const {
    if (identity.isEmpty())
        return agentPlace(m_config.site, m_agentId);
    for (const auto &d : m_devices)
        if (d->device() && d->device()->identity() == identity)
            return d->place();
    // A device this run has not found (yet): its line is the one reached the same way.
    QString line = identity.line;
    QString name;
    if (const int i = m_workspace.lineOf(identity); i >= 0) {
        line = m_workspace.line(i).name;
        name = m_workspace.line(i).deviceName(identity.address);
    }
    return devicePlace(m_config.site, m_agentId, line, name, identity.address,
                       protocol::Catalog::builtin().familyForModel(identity.model));
}

} // namespace tipscope::plant
