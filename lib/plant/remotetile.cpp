#include "remotetile.h"

#include "model/device/portmodel.h"
#include "model/events/problemlevel.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>

namespace tipscope::plant {

namespace {
struct RemoteTileTr {
    Q_DECLARE_TR_FUNCTIONS(RemoteTile)
};

std::optional<qint64> number(const QJsonObject &o, const char *key) {
    const QJsonValue v = o.value(QLatin1String(key));
    return v.isDouble() ? std::optional<qint64>(qRound64(v.toDouble())) : std::nullopt;
}

QString text(const QJsonObject &o, const char *key, const QString &unit = {}) {
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isDouble())
        return unit.isEmpty() ? QLocale().toString(v.toDouble())
                              : QStringLiteral("%1 %2").arg(QLocale().toString(v.toDouble()), unit);
    return v.isString() ? v.toString() : RemoteTileTr::tr("—");
}

// The agents publish stable English words; people read them in their language.
QString statusWords(const QJsonObject &live) {
    const QString word = live.value(QStringLiteral("status")).toString();
    using Mode = model::PortStatus::Mode;
    static const QMap<QString, Mode> modes = {{QStringLiteral("working"), Mode::Working},
                                              {QStringLiteral("stand"), Mode::Stand},
                                              {QStringLiteral("sleep"), Mode::Sleep},
                                              {QStringLiteral("hibernation"), Mode::Hibernation}};
    if (!modes.contains(word))
        return word.isEmpty() ? RemoteTileTr::tr("—") : word;
    model::PortStatus status;
    status.mode = modes.value(word);
    status.cooling = live.value(QStringLiteral("cooling")).toBool();
    return status.text();
}

QString feederWords(const QJsonObject &feeder) {
    const QString word = feeder.value(QStringLiteral("status")).toString();
    return word == QLatin1String("feeding") ? RemoteTileTr::tr("Feeding")
           : word == QLatin1String("idle")  ? RemoteTileTr::tr("Not feeding")
                                            : RemoteTileTr::tr("—");
}

QString feederLine(const QJsonObject &feeder) {
    return RemoteTileTr::tr("%1 · fed %2")
        .arg(feederWords(feeder), text(feeder, "fed_mm", QStringLiteral("mm")));
}

QString problemLine(const QJsonObject &problem) {
    const int port = problem.value(QStringLiteral("port")).toInt();
    const QString what = problem.value(QStringLiteral("text")).toString();
    if (port == 0)
        return what;
    if (problem.value(QStringLiteral("kind")).toString() == QLatin1String("alarm"))
        return RemoteTileTr::tr("Port %1 alarm: %2").arg(port).arg(what);
    return RemoteTileTr::tr("Port %1: %2").arg(port).arg(what);
}

model::Level levelFromWord(const QString &word) {
    if (word == QLatin1String("error"))
        return model::Level::Error;
    if (word == QLatin1String("warning"))
        return model::Level::Warning;
    if (word == QLatin1String("info"))
        return model::Level::Info;
    return model::Level::Warning; // a problem is never shown as less
}

QString offlineText(std::optional<qint64> sinceMs, qint64 nowMs) {
    if (!sinceMs)
        return RemoteTileTr::tr("Agent offline");
    const QDateTime since = QDateTime::fromMSecsSinceEpoch(*sinceMs);
    const QString time = QLocale().toString(since.time(), QStringLiteral("HH:mm"));
    if (since.date() == QDateTime::fromMSecsSinceEpoch(nowMs).date())
        return RemoteTileTr::tr("Agent offline since %1").arg(time);
    return RemoteTileTr::tr("Agent offline since %1 %2")
        .arg(QLocale().toString(since.date(), QLocale::ShortFormat), time);
}
} // namespace

RemoteTile::RemoteTile(const PlantWatch &watch, QString root, QObject *parent)
    : FleetTileSource(parent)
    , m_watch(watch)
    , m_root(std::move(root)) {
    connect(&watch, &PlantWatch::deviceChanged, this, [this](const QString &root) {
        if (root == m_root)
            Q_EMIT changed();
    });
    connect(&watch, &PlantWatch::sampleArrived, this, [this](const QString &root) {
        if (root == m_root)
            Q_EMIT sampleArrived();
    });
}

model::FleetTileState RemoteTile::state() const {
    const RemoteDevice *device = m_watch.device(m_root);
    return device ? remoteTileState(*device, QDateTime::currentMSecsSinceEpoch())
                  : model::FleetTileState{};
}

model::FleetTileState remoteTileState(const RemoteDevice &d, qint64 nowMs) {
    model::FleetTileState s;
    const QString name = d.info.value(QStringLiteral("name")).toString();
    s.deviceName = name.isEmpty() ? d.device : name;
    const QString line = d.info.value(QStringLiteral("line")).toString();
    s.lineName = line.isEmpty() ? d.line : line;
    s.cell = d.site;
    s.model = d.info.value(QStringLiteral("model")).toString();
    QMap<int, model::JointVerdict> portJoints;
    for (const QJsonObject &joint : d.joints)
        if (const auto verdict =
                model::jointVerdictFromName(joint.value(QStringLiteral("verdict")).toString())) {
            const int port = joint.value(QStringLiteral("port")).toInt();
            portJoints.insert(port, *verdict);
            s.lastJoint = verdict;
            s.lastJointPort = port;
        }
    for (const QJsonValue &entry : d.info.value(QStringLiteral("ports")).toArray()) {
        const int number = entry.toObject().value(QStringLiteral("port")).toInt();
        const QJsonObject live = d.live.value(number);
        model::FleetPortState port;
        port.number = number;
        port.tip = plant::number(live, "tip_c");
        port.setpoint = plant::number(live, "set_c");
        port.tipText = text(live, "tip_c", QStringLiteral("°C"));
        port.setpointText = text(live, "set_c", QStringLiteral("°C"));
        port.powerText = text(live, "power_pct", QStringLiteral("%"));
        port.statusText = statusWords(live);
        port.toolText = live.value(QStringLiteral("tool"))
                            .toString(entry.toObject().value(QStringLiteral("tool")).toString());
        if (portJoints.contains(number))
            port.lastJoint = portJoints.value(number);
        s.ports.append(port);
    }
    if (!d.feeder.isEmpty())
        s.feederText = feederLine(d.feeder);
    for (const QJsonValue &entry : d.alarms) {
        const QJsonObject a = entry.toObject();
        s.problems.append(
            {levelFromWord(a.value(QStringLiteral("level")).toString()), problemLine(a)});
    }
    std::stable_sort(s.problems.begin(), s.problems.end(),
                     [](const auto &a, const auto &b) { return a.level > b.level; });
    s.read = !d.live.isEmpty() || !d.feeder.isEmpty() || !d.info.isEmpty();
    s.lineUp = d.online && d.lineUp;
    if (!d.online) {
        s.downSinceMs = d.offlineSinceMs;
        s.lineText = offlineText(d.offlineSinceMs, nowMs);
    } else if (!d.lineUp) {
        s.lineText = model::FleetTile::downText(std::nullopt, nowMs);
    }
    return s;
}

} // namespace tipscope::plant
