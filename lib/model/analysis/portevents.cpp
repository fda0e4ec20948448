#include "model/analysis/portevents.h"

#include <algorithm>

namespace tipscope::model {

namespace {
// As many as a channel can hold samples: no limit in practice.
constexpr int kAll = 1 << 28;
} // namespace

QString PortEvent::kindToken(Kind kind) {
    switch (kind) {
    case Kind::HeatUp:
        return QStringLiteral("heat-up");
    case Kind::Wake:
        return QStringLiteral("wake");
    case Kind::Recovery:
        return QStringLiteral("recovery");
    }
    return {};
}

QList<PortEvent> portEvents(const Telemetry &telemetry, const QList<ChartChannel> &channels,
                            qint64 t0, qint64 t1, qint32 tolerance) {
    QList<PortEvent> out;
    for (const ChartChannel &c : channels) {
        const TelemetryBuffer *buffer = telemetry.buffer(c.key);
        if (c.isFeeder() || !buffer)
            continue;
        const PortMeasurements m = Measurements::measurePort(*buffer, t0, t1, tolerance, kAll);
        for (const HeatUp &h : m.heatUps)
            out.append({c.id, c.port, h.wake ? PortEvent::Kind::Wake : PortEvent::Kind::HeatUp,
                        h.startMs, h.reachedMs, h.target, std::nullopt});
        for (const Recovery &r : m.recoveries)
            out.append({c.id, c.port, PortEvent::Kind::Recovery, r.startMs, r.recoveredMs, r.target,
                        r.lowest});
    }
    std::stable_sort(out.begin(), out.end(), [](const PortEvent &a, const PortEvent &b) {
        return a.startMs != b.startMs ? a.startMs < b.startMs : a.port < b.port;
    });
    return out;
}

} // namespace tipscope::model
