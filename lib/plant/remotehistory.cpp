#include "remotehistory.h"

#include "plantwatch.h"

#include <QDateTime>
#include <QJsonObject>

namespace tipscope::plant {

namespace {
const QStringList kSeries{QStringLiteral("tip"), QStringLiteral("setpoint"),
                          QStringLiteral("power")};
const char *const kFields[] = {"tip_c", "set_c", "power_pct"};

// The sample's values in wire units, or nothing when one of them is missing.
std::optional<QList<qint32>> wireValues(const QJsonObject &sample) {
    QList<qint32> values;
    for (int i = 0; i < kSeries.size(); ++i) {
        const QJsonValue v = sample.value(QLatin1String(kFields[i]));
        if (!v.isDouble())
            return std::nullopt;
        const auto wire = model::seriesFormat(kSeries.at(i), model::TemperatureUnit::Celsius)
                              .toWire(v.toDouble());
        if (!wire)
            return std::nullopt;
        values.append(*wire);
    }
    return values;
}
} // namespace

RemoteHistory::RemoteHistory(const PlantWatch &watch, QObject *parent)
    : QObject(parent)
    , m_watch(watch)
    , m_telemetry(std::make_unique<model::Telemetry>()) {
    connect(&watch, &PlantWatch::portSamplesArrived, this, &RemoteHistory::onSamples);
    connect(&watch, &PlantWatch::deviceChanged, this, &RemoteHistory::onDeviceChanged);
    connect(&watch, &PlantWatch::cleared, this, &RemoteHistory::forget);
}

RemoteHistory::~RemoteHistory() = default;

model::TelemetryKey RemoteHistory::keyOf(const QString &root, int port) {
    return QStringLiteral("%1/port%2").arg(root).arg(port);
}

void RemoteHistory::onSamples(const QString &root, int port, const QJsonArray &samples) {
    const model::TelemetryKey key = keyOf(root, port);
    for (const QJsonValue &s : samples) {
        const QJsonObject sample = s.toObject();
        const QDateTime ts =
            QDateTime::fromString(sample.value(QStringLiteral("ts")).toString(), Qt::ISODateWithMs);
        if (!ts.isValid())
            continue;
        const auto values = wireValues(sample);
        if (!values) {
            m_telemetry->markGap(key, ts.toMSecsSinceEpoch(), model::TelemetryGap::Cause::NoAnswer);
            continue;
        }
        m_telemetry->ensureBuffer(key, kSeries);
        m_telemetry->append(key, ts.toMSecsSinceEpoch(), *values);
    }
}

void RemoteHistory::onDeviceChanged(const QString &root) {
    const RemoteDevice *d = m_watch.device(root);
    if (!d)
        return;
    const bool down = (d->statusKnown && !d->online) || !d->lineUp;
    if (!down) {
        m_down.remove(root);
        return;
    }
    if (m_down.contains(root))
        return;
    m_down.insert(root);
    const qint64 since = d->offlineSinceMs.value_or(QDateTime::currentMSecsSinceEpoch());
    for (auto it = d->live.cbegin(); it != d->live.cend(); ++it)
        m_telemetry->markGap(keyOf(root, it.key()), since, model::TelemetryGap::Cause::LineDown);
}

void RemoteHistory::forget() {
    m_telemetry = std::make_unique<model::Telemetry>();
    m_down.clear();
}

QList<model::ChartChannel> RemoteHistory::channels(const QString &root) const {
    QList<model::ChartChannel> out;
    const RemoteDevice *d = m_watch.device(root);
    if (!d)
        return out;
    for (auto it = d->live.cbegin(); it != d->live.cend(); ++it) {
        const model::TelemetryKey key = keyOf(root, it.key());
        if (!m_telemetry->buffer(key))
            continue;
        model::ChartChannel c;
        c.key = key;
        c.id = QStringLiteral("port%1").arg(it.key());
        c.port = it.key();
        c.title = tr("Port %1").arg(it.key());
        c.deviceModel = d->info.value(QStringLiteral("model")).toString();
        c.tool = it.value().value(QStringLiteral("tool")).toString();
        c.series = kSeries;
        out.append(c);
    }
    return out;
}

QList<model::ChartTrace> RemoteHistory::traces(const QList<model::ChartChannel> &channels) {
    const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine};
    QList<model::ChartTrace> out;
    for (int c = 0; c < channels.size(); ++c)
        for (int s = 0; s < kSeries.size(); ++s) {
            const QString &series = kSeries.at(s);
            out.append({c, series, model::traceName(series, channels.at(c).port),
                        model::portColor(channels.at(c).port), styles[s],
                        model::seriesFormat(series, model::TemperatureUnit::Celsius)});
        }
    return out;
}

} // namespace tipscope::plant
