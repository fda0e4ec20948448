// RemoteApply: a profile applied to a device through the broker, off unless the agent's
// configuration turns it on (`remote_apply`). docs/mqtt.md, "Remote profile apply".
//
// A client publishes a profile (the JSON `tipscope-cli profile save` writes, or {"request_id",
// "profile"}) to `<root>/cmd/apply-profile/<its user name>`. The user-name level is who asks: a
// broker ACL (`pattern write .../cmd/apply-profile/%u`) lets each user publish under its own name
// only, so the name the journal keeps is the broker's, not the sender's word. The profile is
// applied exactly as `tipscope-cli profile apply` applies it (ProfileApplier: checked against the
// limits, each write proved by its read-back) and the outcome is published on `<root>/cmd/result`
// (QoS 1, not retained): what changed, what was already right, what failed and why.
//
// Refused, with a result saying why and nothing written: remote apply turned off, a topic without
// the user level, a retained command (it would run again at every reconnect), a payload that is
// not a profile, a device that is not on the line, an apply already running on the device. Every
// command, carried out or refused, is an event in the journal with the client's name.
#pragma once

#include <QHash>
#include <QObject>
#include <QPointer>
#include <functional>

namespace tipscope::journal {
class Journal;
}
namespace tipscope::model {
class DeviceModel;
class ProfileApplier;
struct ApplyReport;
} // namespace tipscope::model
namespace tipscope::mqtt {
class MqttClient;
}

namespace tipscope::plant {

class RemoteApply : public QObject {
    Q_OBJECT
public:
    // The device published under `root`, or null.
    using DeviceAt = std::function<model::DeviceModel *(const QString &root)>;

    RemoteApply(mqtt::MqttClient &client, journal::Journal &journal, const QString &site,
                bool enabled, DeviceAt deviceAt, QObject *parent = nullptr);
    ~RemoteApply() override;

    // The filter the client subscribes to for the commands of every device of the site.
    [[nodiscard]] static QString commandFilter(const QString &site);

private:
    struct Command;

    void onMessage(const QString &topic, const QByteArray &payload, bool retained);
    void refuse(const Command &command, const QString &reason);
    void finish(const Command &command, const model::ApplyReport &report);
    void answer(const Command &command, bool ok, const QString &error, const QJsonObject &extra);

    mqtt::MqttClient &m_client;
    journal::Journal &m_journal;
    QString m_site;
    bool m_enabled;
    DeviceAt m_deviceAt;
    QHash<QString, QPointer<model::ProfileApplier>> m_running; // by root
};

} // namespace tipscope::plant
