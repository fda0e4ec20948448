#include "telemetry.h"

#include <QLoggingCategory>

namespace tipscope::model {

namespace {
Q_LOGGING_CATEGORY(lcTelemetry, "tipscope.model.telemetry")
} // namespace

Telemetry::Telemetry(QObject *parent)
    : QObject(parent) {
    // Single shot, started by the first sample after a quiet spell: samples arriving while it
    // runs ride along, so a burst costs one signal and a steady stream at most one per interval.
    m_coalesceTimer.setSingleShot(true);
    setMaxSignalsPerSecond(kDefaultMaxSignalsPerSecond);
    connect(&m_coalesceTimer, &QTimer::timeout, this, &Telemetry::emitSamplesAdded);
}

const TelemetryBuffer &Telemetry::ensureBuffer(const TelemetryKey &key, const QStringList &series) {
    return ensureBuffer(key, series, m_tiers);
}

const TelemetryBuffer &Telemetry::ensureBuffer(const TelemetryKey &key, const QStringList &series,
                                               int capacity) {
    return ensureBuffer(key, series, TelemetryTiers::singleTier(capacity));
}

const TelemetryBuffer &Telemetry::ensureBuffer(const TelemetryKey &key, const QStringList &series,
                                               const TelemetryTiers &tiers) {
    auto it = m_entries.find(key);
    if (it == m_entries.end())
        return m_entries.try_emplace(key, TelemetryBuffer(series, tiers)).first->second.buffer;
    const TelemetryBuffer &existing = it->second.buffer;
    if (existing.seriesNames() != series || existing.tiers() != tiers)
        qCWarning(lcTelemetry) << "buffer" << key << "already exists with series"
                               << existing.seriesNames()
                               << "and other tiers; keeping it rather than" << series;
    return existing;
}

bool Telemetry::adoptBuffer(const TelemetryKey &key, TelemetryBuffer &&buffer) {
    return m_entries.try_emplace(key, std::move(buffer)).second;
}

const TelemetryBuffer *Telemetry::buffer(const TelemetryKey &key) const {
    const auto it = m_entries.find(key);
    return it == m_entries.end() ? nullptr : &it->second.buffer;
}

QList<TelemetryKey> Telemetry::keys() const {
    QList<TelemetryKey> result;
    result.reserve(qsizetype(m_entries.size()));
    for (const auto &[key, entry] : m_entries)
        result.append(key);
    return result;
}

AppendResult Telemetry::append(const TelemetryKey &key, qint64 timeMs, const qint32 *values,
                               qsizetype count) {
    const auto it = m_entries.find(key);
    if (it == m_entries.end())
        return AppendResult::UnknownKey;
    const AppendResult result = it->second.buffer.append(timeMs, values, count);
    if (result == AppendResult::Accepted) {
        it->second.changed = true;
        if (!m_coalesceTimer.isActive())
            m_coalesceTimer.start();
    }
    return result;
}

bool Telemetry::markGap(const TelemetryKey &key, qint64 timeMs, TelemetryGap::Cause cause) {
    const auto it = m_entries.find(key);
    if (it == m_entries.end())
        return false;
    if (it->second.buffer.gaps().isOpen())
        return true;
    it->second.buffer.markGap(timeMs, cause);
    it->second.changed = true;
    if (!m_coalesceTimer.isActive())
        m_coalesceTimer.start();
    return true;
}

void Telemetry::setMaxSignalsPerSecond(int rate) {
    m_maxSignalsPerSecond = qBound(1, rate, 1000);
    // Rounded up so that the rate is never exceeded.
    m_coalesceTimer.setInterval((1000 + m_maxSignalsPerSecond - 1) / m_maxSignalsPerSecond);
}

void Telemetry::notifyNow() {
    m_coalesceTimer.stop();
    emitSamplesAdded();
}

void Telemetry::emitSamplesAdded() {
    QList<TelemetryKey> changed;
    for (auto &[key, entry] : m_entries) {
        if (entry.changed)
            changed.append(key);
        entry.changed = false;
    }
    if (!changed.isEmpty())
        Q_EMIT samplesAdded(changed);
}

} // namespace tipscope::model
