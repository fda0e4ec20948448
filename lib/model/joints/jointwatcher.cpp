#include "model/joints/jointwatcher.h"

#include "model/device/displayunits.h"

#include "base/timetext.h"

#include <QCoreApplication>
#include <QLocale>
#include <algorithm>

namespace tipscope::model {

namespace {
struct JointWatcherTr {
    Q_DECLARE_TR_FUNCTIONS(JointWatcher)
};
} // namespace

JointWatcher::JointWatcher(Telemetry &telemetry, QObject *parent)
    : QObject(parent)
    , m_telemetry(telemetry) {
    connect(&m_telemetry, &Telemetry::samplesAdded, this, &JointWatcher::onSamplesAdded);
}

void JointWatcher::watch(StationModel *station,
                         const std::function<TelemetryKey(int port)> &keyOf) {
    for (PortModel *port : station->ports()) {
        const Parameter *power = port->parameter(protocol::Role::Power);
        Channel channel{station->identity(), port->number(), [port] { return port->toolName(); },
                        power ? displayFormat(power->spec(), TemperatureUnit::Celsius).scale
                              : Channel().powerScale};
        watch(station, keyOf(port->number()), std::move(channel));
    }
}

void JointWatcher::watch(QObject *owner, const TelemetryKey &key, Channel channel) {
    const TelemetryBuffer *buffer = m_telemetry.buffer(key);
    const qint64 from = buffer && !buffer->isEmpty() ? buffer->lastTime() + 1 : 0;
    JointDetector detector(channel.device, channel.port);
    QString tool = channel.tool ? channel.tool() : QString();
    m_watched.insert_or_assign(
        key, Watched{owner, std::move(channel), std::move(detector), from, std::move(tool)});
}

void JointWatcher::unwatch(QObject *owner) {
    for (auto it = m_watched.begin(); it != m_watched.end();) {
        if (it->second.owner != owner && it->second.owner) {
            ++it;
            continue;
        }
        emitIfEnded(it->second.detector.gap(it->second.fedUntilMs));
        it = m_watched.erase(it);
    }
}

void JointWatcher::onSamplesAdded(const QList<TelemetryKey> &keys) {
    for (const TelemetryKey &key : keys) {
        const auto it = m_watched.find(key);
        if (it == m_watched.end() || !it->second.owner)
            continue;
        if (const TelemetryBuffer *buffer = m_telemetry.buffer(key))
            feed(it->second, *buffer);
    }
}

// The new samples in time order, with each recorded gap before them as a gap.
void JointWatcher::feed(Watched &w, const TelemetryBuffer &buffer) {
    if (buffer.isEmpty() || buffer.lastTime() < w.fedUntilMs)
        return;
    const qint64 from = w.fedUntilMs;
    const qint64 to = buffer.lastTime() + 1;
    const auto series = [&](const char *name) {
        return buffer.samples(buffer.seriesIndex(QLatin1String(name)), from, to);
    };
    const auto tips = series("tip");
    const auto setpoints = series("setpoint");
    const auto powers = series("power");
    const auto statuses = series("status");
    QList<TelemetryGap> gaps = buffer.gaps().within(from, to);
    qsizetype nextGap = 0;
    const QString tool = w.channel.tool ? w.channel.tool() : QString();
    if (tool != w.tool)
        m_wear.toolChanged(w.channel.device, w.channel.port);
    w.tool = tool;
    w.detector.setLimits(m_rules.limitsFor(w.channel.port, tool));
    for (qsizetype i = 0; i < tips.size(); ++i) {
        const qint64 t = tips.at(i).timeMs;
        while (nextGap < gaps.size() && gaps.at(nextGap).startMs <= t)
            emitIfEnded(w.detector.gap(gaps.at(nextGap++).startMs));
        PortReading r;
        r.timeMs = t;
        r.tip = tips.at(i).value;
        r.setpoint = setpoints.value(i).value;
        r.powerPct = powers.value(i).value * w.channel.powerScale;
        r.working =
            PortStatus::fromNumber(statuses.value(i).value).mode == PortStatus::Mode::Working;
        r.tool = tool;
        emitIfEnded(w.detector.add(r));
    }
    w.fedUntilMs = to;
}

void JointWatcher::emitIfEnded(const std::optional<JointRecord> &joint) {
    if (!joint)
        return;
    Q_EMIT jointEnded(*joint);
    const double share = m_rules.limitsFor(joint->port, joint->tool).wearShare;
    if (const auto notice = m_wear.add(*joint, share))
        Q_EMIT tipWearing(*notice);
}

QString JointWatcher::warningText(const JointRecord &joint, const JointLimits &limits) {
    switch (joint.verdict) {
    case JointVerdict::TooDeep:
        return JointWatcherTr::tr(
                   "joint too deep: the tip fell %1 K below the setpoint (limit %2 K)")
            .arg(QLocale().toString(joint.dipDepth, 'f', 1))
            .arg(limits.maxDipK);
    case JointVerdict::SlowRecovery:
        return joint.recoveryMs ? JointWatcherTr::tr("joint recovered slowly: %1 s (limit %2 s)")
                                      .arg(base::secondsText(*joint.recoveryMs),
                                           base::secondsText(limits.maxRecoveryMs))
                                : JointWatcherTr::tr("joint did not recover within %1 s")
                                      .arg(base::secondsText(joint.durationMs));
    case JointVerdict::Ok:
    case JointVerdict::Incomplete:
        break;
    }
    return {};
}

namespace {
template <typename Watched> bool portSettledUntil(const Watched &w, qint64 timeMs) {
    if (w.fedUntilMs < timeMs)
        return false;
    const std::optional<qint64> since = w.detector.openSinceMs();
    return !since || *since >= timeMs;
}
} // namespace

bool JointWatcher::settledUntil(qint64 timeMs) const {
    return std::all_of(m_watched.begin(), m_watched.end(), [timeMs](const auto &watched) {
        return portSettledUntil(watched.second, timeMs);
    });
}

bool JointWatcher::settledUntil(qint64 timeMs, const DeviceIdentity &device) const {
    return std::all_of(m_watched.begin(), m_watched.end(), [&](const auto &watched) {
        return !(watched.second.channel.device == device) ||
               portSettledUntil(watched.second, timeMs);
    });
}

} // namespace tipscope::model
