#include "remoteapply.h"

#include "planttopics.h"

#include "journal/jointexport.h"
#include "journal/journal.h"
#include "model/device/devicemodel.h"
#include "model/profiles/profileapplier.h"
#include "model/profiles/profilerequest.h"
#include "mqtt/mqttclient.h"
#include "mqtt/mqtttopic.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUuid>

namespace tipscope::plant {

namespace {
struct RemoteApplyTr {
    Q_DECLARE_TR_FUNCTIONS(RemoteApply)
};
const QString kLeaf = QStringLiteral("cmd/apply-profile");
} // namespace

struct RemoteApply::Command {
    QString root;
    QString client; // the user-name level; empty when the topic has none
    QString requestId;
    QPointer<model::DeviceModel> device;
    QByteArray profileSha256;
};

RemoteApply::RemoteApply(mqtt::MqttClient &client, journal::Journal &journal, const QString &site,
                         bool enabled, DeviceAt deviceAt, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_journal(journal)
    , m_site(site)
    , m_enabled(enabled)
    , m_deviceAt(std::move(deviceAt)) {
    (void)m_client.subscribe(commandFilter(site), 1); // kept and sent again on every reconnect
    connect(&client, &mqtt::MqttClient::messageReceived, this, &RemoteApply::onMessage);
}

RemoteApply::~RemoteApply() {
    for (const auto &applier : std::as_const(m_running))
        if (applier)
            applier->cancel();
}

QString RemoteApply::commandFilter(const QString &site) {
    // `#` also matches the level before it: the topic without a user name is heard, and refused.
    return QStringLiteral("%1/%2/+/+/%3/#")
        .arg(QLatin1String(kTopicPrefix), mqtt::sanitizeTopicLevel(site), kLeaf);
}

void RemoteApply::onMessage(const QString &topic, const QByteArray &payload, bool retained) {
    const auto where = parseDeviceTopic(topic);
    if (!where || !where->leaf.startsWith(kLeaf))
        return;
    Command command;
    command.root = deviceRoot(where->site, where->line, where->device);
    command.client = where->leaf.mid(kLeaf.size() + 1);
    // Read first, so that every answer, a refusal too, carries the request's id when it has one.
    const model::ProfileRequest request = model::ProfileRequest::parse(payload);
    command.requestId = request.requestId;
    if (command.requestId.isEmpty())
        command.requestId = QUuid::createUuid().toString(QUuid::WithoutBraces);
    if (retained)
        return refuse(command,
                      RemoteApplyTr::tr("a retained command is not carried out: it would run again "
                                        "at every reconnect"));
    if (!m_enabled)
        return refuse(command, RemoteApplyTr::tr(
                                   "remote profile apply is off in this agent's configuration"));
    if (command.client.isEmpty() || command.client.contains(QLatin1Char('/')))
        return refuse(command,
                      RemoteApplyTr::tr("publish the command under your user name: %1/%2/USER")
                          .arg(command.root, kLeaf));
    command.device = m_deviceAt(command.root);
    if (!command.device)
        return refuse(
            command,
            RemoteApplyTr::tr("no device of this agent is published at %1").arg(command.root));
    if (m_running.value(command.root))
        return refuse(command,
                      RemoteApplyTr::tr("another profile is being applied to this device"));
    const auto &profile = request.profile;
    if (!profile)
        return refuse(command, RemoteApplyTr::tr("profile refused: %1").arg(profile.error()));
    command.profileSha256 =
        QCryptographicHash::hash(profile->toJson(), QCryptographicHash::Sha256).toHex();
    auto *applier = new model::ProfileApplier(*command.device, profile.value(),
                                              model::ProfileApplier::Mode::Apply, false, this);
    m_running.insert(command.root, applier);
    connect(applier, &model::ProfileApplier::finished, this,
            [this, command, applier](const model::ApplyReport &report) {
                m_running.remove(command.root);
                applier->deleteLater();
                finish(command, report);
            });
    applier->start();
}

void RemoteApply::refuse(const Command &command, const QString &reason) {
    answer(command, false, reason, {});
}

void RemoteApply::finish(const Command &command, const model::ApplyReport &report) {
    QJsonArray changed;
    for (const model::ApplyItem &item : report.written)
        changed.append(QJsonObject{{QStringLiteral("code"), QString::fromLatin1(item.code)},
                                   {QStringLiteral("name"), item.name},
                                   {QStringLiteral("before"), item.before},
                                   {QStringLiteral("after"), item.after},
                                   {QStringLiteral("ok"), item.ok},
                                   {QStringLiteral("reason"), item.reason}});
    QString error = report.refused ? report.reason : report.conflictReason();
    if (error.isEmpty() && report.failedCount() > 0)
        error = RemoteApplyTr::tr("%n setting(s) not taken", nullptr, report.failedCount());
    answer(command, report.ok(), error,
           {{QStringLiteral("changed"), changed},
            {QStringLiteral("unchanged"), report.unchanged},
            {QStringLiteral("conflicts"), QJsonArray::fromStringList(report.conflicts)}});
}

void RemoteApply::answer(const Command &command, bool ok, const QString &error,
                         const QJsonObject &extra) {
    QJsonObject result{
        {QStringLiteral("ts"), journal::utcText(QDateTime::currentMSecsSinceEpoch())},
        {QStringLiteral("request_id"), command.requestId},
        {QStringLiteral("command"), QStringLiteral("apply-profile")},
        {QStringLiteral("client"), command.client},
        {QStringLiteral("ok"), ok},
        {QStringLiteral("profile_sha256"), QString::fromLatin1(command.profileSha256)}};
    if (!error.isEmpty())
        result.insert(QStringLiteral("error"), error);
    for (auto it = extra.begin(); it != extra.end(); ++it)
        result.insert(it.key(), it.value());
    (void)m_client.publish(command.root + QStringLiteral("/cmd/result"),
                           QJsonDocument(result).toJson(QJsonDocument::Compact), 1, false);
    // The journal keeps who asked, whatever came of it; the apply's own event has its changes.
    journal::JournalEvent event;
    event.kind = journal::JournalEvent::Kind::ProfileApply;
    event.severity =
        ok ? journal::JournalEvent::Severity::Info : journal::JournalEvent::Severity::Warning;
    if (command.device)
        event.device = command.device->identity();
    event.text = ok ? RemoteApplyTr::tr("Profile applied through MQTT for %1").arg(command.client)
                    : RemoteApplyTr::tr("Profile through MQTT for %1 not applied: %2")
                          .arg(command.client.isEmpty() ? RemoteApplyTr::tr("an unnamed client")
                                                        : command.client,
                               error);
    event.details = {{QStringLiteral("client"), command.client},
                     {QStringLiteral("requestId"), command.requestId},
                     {QStringLiteral("topic"), command.root + QLatin1Char('/') + kLeaf},
                     {QStringLiteral("ok"), ok},
                     {QStringLiteral("profileSha256"), QString::fromLatin1(command.profileSha256)}};
    m_journal.append(event);
}

} // namespace tipscope::plant
