// The heat-ups and recoveries of every port of a recording (or of any telemetry), one after the
// other in time order, each with its channel: what tipscope-cli measure prints, line by line, and
// what a front end without a screen reports joint by joint. Measurements::measurePort() finds
// them, as for the Charts page's panel; here over the whole span, with no limit on their number.
#pragma once

#include "model/analysis/measurements.h"
#include "model/chart/chartseries.h"

namespace tipscope::model {

struct PortEvent {
    enum class Kind { HeatUp, Wake, Recovery };

    QString channel; // "port1"
    int port = 0;
    Kind kind = Kind::HeatUp;
    qint64 startMs = 0;
    std::optional<qint64> endMs;  // reached or recovered; nullopt when the data ended first
    qint32 target = 0;            // the setpoint, wire units
    std::optional<qint32> lowest; // a recovery's lowest tip temperature, wire units

    // "heat-up", "wake", "recovery": stable words for data, whatever the language.
    [[nodiscard]] static QString kindToken(Kind kind);
};

// Every heat-up, wake and recovery of the port channels over [t0, t1), by start time (and port).
// `tolerance` in wire units (°C), as for Measurements::measurePort().
[[nodiscard]] QList<PortEvent> portEvents(const Telemetry &telemetry,
                                          const QList<ChartChannel> &channels, qint64 t0, qint64 t1,
                                          qint32 tolerance);

} // namespace tipscope::model
