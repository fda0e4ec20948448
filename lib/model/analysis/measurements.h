// Measurements engineers ask of a tip curve, over a window of one port's telemetry ("tip",
// "setpoint", "status" series, wire units):
//
// - heat-up: from a setpoint change, or from waking out of sleep or hibernation into working,
//   until the tip is first within ±tolerance of the setpoint; it starts where the tip began to
//   move toward the new target, which may be before the status or setpoint was read;
// - recovery: while working at a steady setpoint and after the tip had settled, from the first
//   sample under setpoint − tolerance (a joint drew heat) until it is back within the band, with
//   the lowest temperature of the dip. A dip with no power where the tip is lowest and none at
//   its end is the heater off (no tool, a port error), not a joint: it is left out.
//
// Rests (stand, sleep, hibernation, cooling) are no dips. A setpoint of 0 is "not read yet" (the
// session records 0 until the station answered), so changes from it are no heat-ups. A change or
// dip that runs past the end of the window has no end time. The work is bounded by the decimation,
// not the history: changes and band crossings are located on the buffer's min/max columns and only
// the columns that can hold one are read sample by sample, so a 24-hour window costs about as much
// as a minute. Only full-rate samples are measured: a window reaching into a tiered buffer's
// older summaries is measured from TelemetryBuffer::fullRateFrom() on.
#pragma once

#include "model/telemetry/telemetrybuffer.h"

#include <QList>
#include <optional>

namespace tipscope::model {

struct HeatUp {
    qint64 startMs = 0; // where the tip began to move after a setpoint change or a wake
    qint32 target = 0;  // the setpoint, wire units
    bool wake = false;
    std::optional<qint64> reachedMs;
};

struct Recovery {
    qint64 startMs = 0; // first sample under the band
    qint32 target = 0;
    qint32 lowest = 0;
    qint64 lowestMs = 0;
    std::optional<qint64> recoveredMs;
};

struct PortMeasurements {
    QList<HeatUp> heatUps;
    QList<Recovery> recoveries;
    bool truncated = false; // more than the results asked for of either; the first are kept
};

class Measurements {
public:
    static constexpr int kMaxResults = 200;

    // Times in [t0, t1) of the samples whose value differs from the sample before them, the
    // first `maxChanges` of them.
    [[nodiscard]] static QList<qint64> changeTimes(const TelemetryBuffer &buffer, int series,
                                                   qint64 t0, qint64 t1,
                                                   int maxChanges = 4 * kMaxResults);
    // The first sample of [t0, t1) within [low, high], or under `low` for firstBelow().
    [[nodiscard]] static std::optional<qint64> firstWithin(const TelemetryBuffer &buffer,
                                                           int series, qint64 t0, qint64 t1,
                                                           qint32 low, qint32 high);
    [[nodiscard]] static std::optional<qint64> firstBelow(const TelemetryBuffer &buffer, int series,
                                                          qint64 t0, qint64 t1, qint32 limit);
    // `tolerance` in wire units (°C). Empty unless the buffer has tip, setpoint and status. The
    // panel lists a window's first kMaxResults of each; a whole recording (tipscope-cli
    // measure) asks for more.
    [[nodiscard]] static PortMeasurements measurePort(const TelemetryBuffer &buffer, qint64 t0,
                                                      qint64 t1, qint32 tolerance,
                                                      int maxResults = kMaxResults);

private:
    // measurePort() over a window that holds no gap.
    [[nodiscard]] static PortMeasurements measureStretch(const TelemetryBuffer &buffer, qint64 t0,
                                                         qint64 t1, qint32 tolerance,
                                                         int maxResults);
};

} // namespace tipscope::model
