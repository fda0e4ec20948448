// PlantWatch: the plant as the broker shows it, for a TipScope window that watches other line
// PCs: subscribes to `tipscope/v1/<site>/#` (every site when none is named) and keeps, per device
// root, the last of what its agent published (docs/mqtt.md): presence, info, each port's live
// values, the feeder's, the errors and alarms in force, the counters and the recent joints.
// Nothing is published: a watcher only reads.
//
// A device is known from its first message on; deviceChanged() comes for every message about it
// (its root), sampleArrived() for each live message. What a publisher may declare is bounded
// (plantwatchlimits.h): a message beyond it is refused whole and logged once per publisher, so
// that what the watcher keeps stays within a bound whatever the broker holds. A device whose agent
// went offline keeps what it published, marked by `online` false and since when, so a view shows it
// as not current.
#pragma once

#include "planttopics.h"

#include "mqtt/mqttclient.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QMap>
#include <QObject>
#include <QSet>
#include <memory>
#include <optional>

namespace tipscope::plant {

struct RemoteDevice {
    static constexpr int kMaxJoints = 200;

    QString root;               // tipscope/v1/<site>/<line>/<device>
    QString site, line, device; // the topic's levels
    bool statusKnown = false;
    bool online = false;
    bool lineUp = true;
    std::optional<qint64> offlineSinceMs; // when the watcher saw it go, or the will's time
    QJsonObject status;
    QJsonObject info;
    QMap<int, QJsonObject> live; // by port
    QJsonObject feeder;
    QJsonArray alarms;
    QJsonObject counters;
    QList<QJsonObject> joints; // oldest first, the newest kMaxJoints
    qint64 lastLiveMs = 0;     // when the watcher received the last live message
};

class PlantWatch : public QObject {
    Q_OBJECT
public:
    explicit PlantWatch(QObject *parent = nullptr);
    ~PlantWatch() override;

    // Connects to `broker` and subscribes to the devices of `site` (sanitized as a topic level;
    // empty: every site). Again: forgets what it knew and starts over.
    void start(const mqtt::MqttSettings &broker, const QString &site);
    void stop();

    [[nodiscard]] mqtt::MqttClient &client() const { return *m_client; }
    [[nodiscard]] QString filter() const { return m_filter; }
    [[nodiscard]] QStringList roots() const { return m_devices.keys(); }
    [[nodiscard]] const RemoteDevice *device(const QString &root) const;

Q_SIGNALS:
    void deviceAdded(const QString &root);
    void deviceChanged(const QString &root);
    void sampleArrived(const QString &root);
    // Every sample of a port's live message (a batch has several), oldest first.
    void portSamplesArrived(const QString &root, int port, const QJsonArray &samples);
    void cleared();

private:
    void onMessage(const QString &topic, const QByteArray &payload, bool retained);
    void refuse(const QString &who, const QString &why);
    [[nodiscard]] QString countProblem(const DeviceTopic &where, QString *who) const;

    std::unique_ptr<mqtt::MqttClient> m_client;
    QString m_filter;
    QMap<QString, RemoteDevice> m_devices;
    QSet<QString> m_said; // publishers, lines and sites whose refusal was logged
    bool m_saidEnough = false;
};

} // namespace tipscope::plant
