// DevicePublisher: one device of a line on MQTT, under its root (planttopics.h): its presence
// (`status`), what it is (`info`), its live values (`port/<n>/live`, `feeder/live`), its counters
// and its errors and alarms in force. Joints and events go through the JournalForwarder instead.
//
// Presence needs a connection of its own: MQTT has one last will per connection, and each
// device's `status` must turn {"online": false} when the agent dies. So each device has a small
// client whose will is its offline status and which publishes its online status, retained, each
// time it connects. Everything else goes through the shared client, retained topics again after
// each connection (a broker that restarted without persistence has forgotten them).
//
// Live values are published as they are read, at most one message per port each interval (the
// interval is kept on average: a reading is sent when the next slot is due), with the reading's
// own time, so a subscriber's latency is the wire's, not a timer's. With batching, the samples of
// batchMs go out as one list (also when readings stop, and before going offline). Nothing is
// published for a port that was not read: a gap stays a gap. Counters go out at start, every
// countersIntervalS, when all are first read, and at once when one goes down (a reset); alarms when
// the set in force changes; info when a tool changes.
#pragma once

#include "agentconfig.h"
#include "plantpayloads.h"
#include "planttopics.h"

#include <QElapsedTimer>
#include <QHash>
#include <QJsonArray>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <memory>

namespace tipscope::model {
class DeviceModel;
class Parameter;
} // namespace tipscope::model
namespace tipscope::mqtt {
class MqttClient;
}

namespace tipscope::plant {

class DevicePublisher : public QObject {
    Q_OBJECT
public:
    DevicePublisher(mqtt::MqttClient &shared, const AgentConfig &config, const Publisher &who,
                    model::DeviceModel &device, DevicePlace place, QObject *parent = nullptr);
    ~DevicePublisher() override;

    [[nodiscard]] const DevicePlace &place() const { return m_place; }
    [[nodiscard]] model::DeviceModel *device() const { return m_device; }
    [[nodiscard]] mqtt::MqttClient &presence() const { return *m_presence; }
    [[nodiscard]] qint64 liveCount() const { return m_liveCount; }
    // The broker acknowledged the offline status goOffline() published.
    [[nodiscard]] bool isOfflineConfirmed() const { return m_offlineConfirmed; }

    // Publishes {"online": false} through the presence client; offline() comes when the broker
    // acknowledged it, or at once when the client is not connected.
    void goOffline();
    // Everything retained again, after the shared client (re)connected.
    void publishRetained();
    // Hands over to a successor (a reload): the presence client disconnects cleanly, so the broker
    // drops its will and the device does not flash offline; `sayOffline` first publishes offline
    // (the successor publishes under another root). Deletes itself once disconnected.
    void retire(bool sayOffline);

Q_SIGNALS:
    void offline();

private:
    struct LiveSlot {
        qint64 dueMs = 0;
        QJsonArray batch;
    };

    void publishStatus();
    // {"online": false} through the presence client, retained; its message id, 0 if refused.
    int publishOffline();
    void publishInfo();
    void publishCounters();
    void publishAlarms(bool always);
    void onParameterChanged(model::Parameter *parameter);
    void onReading(int port, model::Parameter *timeSource);
    void sendLive(int port, const QJsonObject &payload);
    void flushBatches();
    [[nodiscard]] QString liveTopic(int port) const;
    void publish(const QString &leaf, const QJsonObject &payload, int qos, bool retain);

    mqtt::MqttClient &m_shared;
    AgentConfig m_config;
    Publisher m_who;
    QPointer<model::DeviceModel> m_device;
    DevicePlace m_place;
    std::unique_ptr<mqtt::MqttClient> m_presence;
    QHash<int, LiveSlot> m_live; // by port; 0 is the feeder
    QHash<QByteArray, qint64> m_counterValues;
    bool m_countersComplete = false;
    QJsonArray m_alarms;
    bool m_alarmsPublished = false;
    QTimer m_countersTimer;
    QTimer m_infoTimer;  // tools are read one port at a time: one info for all of them
    QTimer m_batchTimer; // a batch goes out on time even when readings stop
    int m_offlineId = 0;
    bool m_offlineConfirmed = false;
    qint64 m_liveCount = 0;
};

} // namespace tipscope::plant
