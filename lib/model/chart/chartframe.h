// ChartFrame: what one redraw of a pane puts on screen, computed from the telemetry buffers and
// nothing else, so that a redraw costs in proportion to the plot's width in pixels, never to the
// length of the history.
//
// For each trace the visible window [t0, t1) is split into one time column per pixel and the
// buffer's exact min/max decimation gives at most two points per column, in time order, at the
// times the extremes occurred: a one-sample spike always reaches the screen. Of a run of points at
// one height only the ends are kept (the line between them is the same). The newest sample
// before t0 leads each curve so it enters from the left edge instead of starting mid-plot.
//
// The readout is the crosshair's answer at one instant: each trace's newest sample at or before
// it, straight from the buffer (not from the decimated points), in display units.
#pragma once

#include "model/chart/chartseries.h"

#include "model/telemetry/telemetry.h"

#include <QPointF>

namespace tipscope::model {

struct ValueSpan {
    double min = 0;
    double max = 0;
    bool valid = false;

    void include(double v);
    void include(const ValueSpan &other);
};

struct ChartFrame {
    qint64 t0 = 0;
    qint64 t1 = 0;
    QList<QList<QPointF>> points; // one list per trace; x in ms since the epoch
    ValueSpan left, right;        // the extremes drawn on each axis (the lead-in point aside)
    qint64 pointCount = 0;
};

// The points of one series over [t0, t1) at `columns` columns, in display units.
[[nodiscard]] QList<QPointF> minMaxPoints(const TelemetryBuffer &buffer, int series, qint64 t0,
                                          qint64 t1, int columns, const SeriesFormat &format,
                                          ValueSpan *span = nullptr);

[[nodiscard]] ChartFrame buildFrame(const Telemetry &telemetry, const QList<ChartChannel> &channels,
                                    const QList<ChartTrace> &traces, qint64 t0, qint64 t1,
                                    int columns);

struct ReadoutValue {
    int trace = 0;
    bool valid = false;  // false when the trace has no sample at or before the instant
    qint64 sampleMs = 0; // the time of the sample shown
    qint32 wire = 0;
    double display = 0;
};

[[nodiscard]] QList<ReadoutValue> readoutAt(const Telemetry &telemetry,
                                            const QList<ChartChannel> &channels,
                                            const QList<ChartTrace> &traces, qint64 timeMs);
// "12:03:04.250  P1 tip 351 °C · P1 setpoint 350 °C · P1 power 12.5 %".
[[nodiscard]] QString readoutText(const QList<ChartTrace> &traces,
                                  const QList<ReadoutValue> &values, qint64 timeMs);
// The same without the time: "P1 tip 351 °C · P1 setpoint 350 °C · …", "—" where a series has
// no sample.
[[nodiscard]] QString readoutValuesText(const QList<ChartTrace> &traces,
                                        const QList<ReadoutValue> &values);
// The same, one text per channel (a port's tip, setpoint and power together), in trace order:
// the cells a readout lays out side by side or one under the other as its width allows.
[[nodiscard]] QStringList readoutCells(const QList<ChartTrace> &traces,
                                       const QList<ReadoutValue> &values);
inline const QString kReadoutJoin = QStringLiteral(" · ");
[[nodiscard]] QString readoutTimeText(qint64 timeMs);

// A round axis range around `span` (steps of 1, 2, 5 × 10^n) with a little headroom, so a
// follow-mode axis does not twitch with every new sample.
[[nodiscard]] ValueSpan niceRange(const ValueSpan &span, double minimumWidth);

} // namespace tipscope::model
