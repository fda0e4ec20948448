#include "plantwatch.h"

#include "planttopics.h"
#include "plantwatchlimits.h"

#include "mqtt/mqtttopic.h"

#include "base/elide.h"

#include <QDateTime>
#include <QJsonDocument>
#include <QLoggingCategory>
#include <utility>

Q_LOGGING_CATEGORY(lcWatch, "tipscope.plant.watch")

namespace tipscope::plant {

PlantWatch::PlantWatch(QObject *parent)
    : QObject(parent)
    , m_client(std::make_unique<mqtt::MqttClient>()) {}

PlantWatch::~PlantWatch() = default;

void PlantWatch::start(const mqtt::MqttSettings &broker, const QString &site) {
    stop();
    m_client = std::make_unique<mqtt::MqttClient>();
    mqtt::MqttSettings settings = broker;
    settings.cleanSession = true; // a watcher wants the retained state, not a backlog
    m_client->setSettings(settings);
    m_filter = QStringLiteral("%1/%2/#").arg(
        QLatin1String(kTopicPrefix),
        site.trimmed().isEmpty() ? QStringLiteral("+") : mqtt::sanitizeTopicLevel(site));
    (void)m_client->subscribe(m_filter, 1);
    connect(m_client.get(), &mqtt::MqttClient::messageReceived, this, &PlantWatch::onMessage);
    m_client->start();
}

void PlantWatch::stop() {
    m_client->stop();
    m_said.clear();
    m_saidEnough = false;
    if (!m_devices.isEmpty()) {
        m_devices.clear();
        Q_EMIT cleared();
    }
}

const RemoteDevice *PlantWatch::device(const QString &root) const {
    const auto it = m_devices.constFind(root);
    return it == m_devices.cend() ? nullptr : &*it;
}

// Logged once per publisher (device root), line or site; the set of those said is bounded too, so
// a broker of endless hostile roots cannot grow it.
void PlantWatch::refuse(const QString &publisher, const QString &why) {
    const QString who = publisher.left(256);
    if (m_said.contains(who))
        return;
    if (m_said.size() >= PlantWatchLimits::kMaxDevices * 2) {
        if (!std::exchange(m_saidEnough, true))
            qCWarning(lcWatch, "more publishers refused; no more are logged");
        return;
    }
    m_said.insert(who);
    qCWarning(lcWatch, "%s refused: %s", qPrintable(base::elided(who, 160)), qPrintable(why));
}

// Empty when a device at `where` may be added, else why not (and who is told).
QString PlantWatch::countProblem(const DeviceTopic &where, QString *who) const {
    using L = PlantWatchLimits;
    for (const QString &level : {where.site, where.line, where.device})
        if (level.size() > L::kMaxLevelChars) {
            *who = QStringLiteral("a topic");
            return QStringLiteral("a topic level of %1 characters (at most %2)")
                .arg(level.size())
                .arg(L::kMaxLevelChars);
        }
    if (m_devices.size() >= L::kMaxDevices) {
        *who = QStringLiteral("the plant");
        return QStringLiteral("more than %1 devices").arg(L::kMaxDevices);
    }
    QSet<QString> lines;
    int onLine = 0;
    for (const RemoteDevice &d : m_devices) {
        if (d.site != where.site)
            continue;
        lines.insert(d.line);
        onLine += d.line == where.line ? 1 : 0;
    }
    if (onLine >= L::kMaxDevicesPerLine) {
        *who = QStringLiteral("line %1/%2").arg(where.site, where.line);
        return QStringLiteral("more than %1 devices on the line").arg(L::kMaxDevicesPerLine);
    }
    if (!lines.contains(where.line) && lines.size() >= L::kMaxLinesPerSite) {
        *who = QStringLiteral("site %1").arg(where.site);
        return QStringLiteral("more than %1 lines").arg(L::kMaxLinesPerSite);
    }
    return {};
}

void PlantWatch::onMessage(const QString &topic, const QByteArray &payload, bool) {
    const auto where = parseDeviceTopic(topic);
    if (!where || where->leaf.startsWith(QLatin1String("cmd/")))
        return;
    const QString root = deviceRoot(where->site, where->line, where->device);
    QJsonObject json;
    if (const QString why = watchedMessageProblem(where->leaf, payload, &json); !why.isEmpty())
        return refuse(root, why);
    const bool added = !m_devices.contains(root);
    QString who;
    if (const QString why = added ? countProblem(*where, &who) : QString(); !why.isEmpty())
        return refuse(who, why);
    RemoteDevice &d = m_devices[root];
    if (added) {
        d.root = root;
        d.site = where->site;
        d.line = where->line;
        d.device = where->device;
    }
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const QString &leaf = where->leaf;
    bool sample = false;
    std::optional<std::pair<int, QJsonArray>> portSamples;
    if (leaf == QLatin1String("status")) {
        const bool online = json.value(QStringLiteral("online")).toBool();
        // Seen go: now. Found gone: the clean stop's time; a will's is not when it went.
        if (!online && d.statusKnown && d.online)
            d.offlineSinceMs = now;
        else if (!online && !d.statusKnown && !json.value(QStringLiteral("will")).toBool())
            d.offlineSinceMs = QDateTime::fromString(json.value(QStringLiteral("ts")).toString(),
                                                     Qt::ISODateWithMs)
                                   .toMSecsSinceEpoch();
        if (online)
            d.offlineSinceMs.reset();
        d.statusKnown = true;
        d.online = online;
        d.lineUp = json.value(QStringLiteral("line_up")).toBool(true);
        d.status = json;
    } else if (leaf == QLatin1String("info")) {
        d.info = json;
    } else if (leaf == QLatin1String("alarms")) {
        d.alarms = json.value(QStringLiteral("alarms")).toArray();
    } else if (leaf == QLatin1String("counters")) {
        d.counters = json;
    } else if (leaf == QLatin1String("joint")) {
        const QString id = json.value(QStringLiteral("id")).toString();
        const bool seen = std::any_of(d.joints.cbegin(), d.joints.cend(), [&id](const auto &j) {
            return j.value(QStringLiteral("id")).toString() == id;
        }); // QoS 1 may deliver a joint twice
        if (!seen)
            d.joints.append(json);
        while (d.joints.size() > RemoteDevice::kMaxJoints)
            d.joints.removeFirst();
    } else if (leaf == QLatin1String("feeder/live")) {
        d.feeder = json;
        d.lastLiveMs = now;
        sample = true;
    } else if (leaf.startsWith(QLatin1String("port/")) && leaf.endsWith(QLatin1String("/live"))) {
        bool ok = false;
        const int port = leaf.section(QLatin1Char('/'), 1, 1).toInt(&ok);
        if (!ok)
            return;
        // A batch: its newest sample is what the port shows now.
        QJsonArray samples = json.value(QStringLiteral("samples")).toArray();
        if (samples.isEmpty())
            samples.append(json);
        d.live.insert(port, samples.last().toObject());
        d.lastLiveMs = now;
        sample = true;
        portSamples = {port, samples};
    }
    if (added)
        Q_EMIT deviceAdded(root);
    Q_EMIT deviceChanged(root);
    if (portSamples)
        Q_EMIT portSamplesArrived(root, portSamples->first, portSamples->second);
    if (sample)
        Q_EMIT sampleArrived(root);
}

} // namespace tipscope::plant
