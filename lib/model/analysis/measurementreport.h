// The measurement panel's text: for each channel of a window, min/max/mean of every series drawn,
// then (ports) the heat-ups and recoveries Measurements finds, newest first, in the display units
// the charts use. Plain text, one line per fact, so it can be copied into a report.
#pragma once

#include "model/chart/chartseries.h"

#include "model/telemetry/telemetry.h"

namespace tipscope::model {

struct MeasurementRequest {
    qint64 t0 = 0;
    qint64 t1 = 0;
    qint32 toleranceWire = 5; // °C
    TemperatureUnit unit = TemperatureUnit::Celsius;
    int maxListed = 5; // heat-ups and recoveries listed per port; the rest are counted
    // As drawn: the transistor's stats per port, and the transformer's once per station.
    bool hardware = false;
};

[[nodiscard]] QString measurementReport(const Telemetry &telemetry,
                                        const QList<ChartChannel> &channels,
                                        const MeasurementRequest &request);
// "12.3 s", "2 min 05 s", "1 h 02 min".
[[nodiscard]] QString durationText(qint64 ms);

} // namespace tipscope::model
