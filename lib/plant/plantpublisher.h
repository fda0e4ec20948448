// PlantPublisher: a workspace's lines on MQTT. One shared client publishes every device's info,
// live values, counters and alarms (a DevicePublisher each) and forwards the journal's joints and
// events (JournalForwarder); each device also has its presence client (devicepublisher.h).
//
// start() (again) applies a configuration: clients are made anew, so a changed broker, identity
// or password takes effect, and the journal is forwarded again from its oldest unsent record.
// Devices are followed as the workspace finds and loses them. stop() publishes every device's
// {"online": false}, waits for the broker's acknowledgements (at most stopTimeoutMs), disconnects
// and emits stopped(). The workspace and the journal must outlive the publisher.
#pragma once

#include "agentconfig.h"
#include "devicepublisher.h"
#include "journalforwarder.h"
#include "remoteapply.h"

#include <QObject>
#include <QTimer>
#include <memory>
#include <vector>

namespace tipscope::model {
class Workspace;
}
namespace tipscope::journal {
class Journal;
}

namespace tipscope::plant {

class PlantPublisher : public QObject {
    Q_OBJECT
public:
    PlantPublisher(model::Workspace &workspace, journal::Journal &journal,
                   QObject *parent = nullptr);
    ~PlantPublisher() override;

    void start(const AgentConfig &config, const Publisher &who);
    void stop(int stopTimeoutMs = 3000);

    [[nodiscard]] bool isRunning() const { return m_client != nullptr; }
    [[nodiscard]] mqtt::MqttClient *client() const { return m_client.get(); }
    [[nodiscard]] JournalForwarder *forwarder() const { return m_forwarder.get(); }
    [[nodiscard]] const std::vector<std::unique_ptr<DevicePublisher>> &devices() const {
        return m_devices;
    }
    [[nodiscard]] QString agentId() const { return m_agentId; }
    // Where records about `device` go, also for one the workspace no longer has.
    [[nodiscard]] DevicePlace placeOf(const model::DeviceIdentity &device) const;

Q_SIGNALS:
    void stopped();
    // A device appeared on MQTT, or went.
    void devicesChanged();

private:
    void syncAll();
    void syncLine(int index);
    void addDevice(int index, model::DeviceModel &device);
    void onOffline();
    void finishStop();

    model::Workspace &m_workspace;
    journal::Journal &m_journal;
    AgentConfig m_config;
    Publisher m_who;
    QString m_agentId;
    std::unique_ptr<mqtt::MqttClient> m_client;
    std::unique_ptr<JournalForwarder> m_forwarder;
    std::unique_ptr<RemoteApply> m_remoteApply;
    std::vector<std::unique_ptr<DevicePublisher>> m_devices;
    int m_awaitingOffline = 0;
    QTimer m_stopTimer;
};

} // namespace tipscope::plant
