#include "model/chart/chartframe.h"

#include <QDateTime>
#include <QLocale>
#include <cmath>
#include <optional>

namespace tipscope::model {

void ValueSpan::include(double v) {
    if (!valid) {
        min = max = v;
        valid = true;
        return;
    }
    min = qMin(min, v);
    max = qMax(max, v);
}

void ValueSpan::include(const ValueSpan &other) {
    if (other.valid) {
        include(other.min);
        include(other.max);
    }
}

namespace {
// Appends `p`, dropping the middle of three points at one height: a flat run (a setpoint, a
// saturated power) needs only its ends, and every point costs Qt Charts a stroke.
void appendPoint(QList<QPointF> &points, const QPointF &p) {
    const qsizetype n = points.size();
    if (n >= 2 && points.at(n - 1).y() == p.y() && points.at(n - 2).y() == p.y())
        points.last() = p;
    else
        points.append(p);
}
} // namespace

namespace {
// The points of already decimated columns; `lead` is the last sample before the window, so the
// curve enters the window from the left edge rather than starting at the first column. Where a
// gap of `gaps` (sorted) begins between two points, a point with no value (NaN) breaks the curve:
// nothing was measured there, and a line across it would invent the values.
QList<QPointF> pointsOf(const QList<MinMaxBucket> &buckets,
                        const std::optional<TelemetryBuffer::Sample> &lead,
                        const QList<TelemetryGap> &gaps, const SeriesFormat &format,
                        ValueSpan *span) {
    QList<QPointF> points;
    points.reserve(buckets.size() * 2 + 1 + gaps.size());
    if (lead)
        points.append(QPointF(double(lead->timeMs), format.toDisplay(lead->value)));
    qsizetype nextGap = 0;
    for (const MinMaxBucket &b : buckets) {
        const qint64 first = qMin(b.minTimeMs, b.maxTimeMs);
        bool broken = false;
        for (; nextGap < gaps.size() && gaps.at(nextGap).startMs <= first; ++nextGap)
            broken = broken || (!points.isEmpty() && points.last().x() < gaps.at(nextGap).startMs);
        if (broken)
            points.append(QPointF(double(gaps.at(nextGap - 1).startMs), qQNaN()));
        const QPointF low(double(b.minTimeMs), format.toDisplay(b.min));
        const QPointF high(double(b.maxTimeMs), format.toDisplay(b.max));
        if (span) {
            span->include(low.y());
            span->include(high.y());
        }
        if (b.min == b.max) {
            appendPoint(points, low);
        } else if (b.minTimeMs <= b.maxTimeMs) {
            appendPoint(points, low);
            appendPoint(points, high);
        } else {
            appendPoint(points, high);
            appendPoint(points, low);
        }
    }
    return points;
}
} // namespace

QList<QPointF> minMaxPoints(const TelemetryBuffer &buffer, int series, qint64 t0, qint64 t1,
                            int columns, const SeriesFormat &format, ValueSpan *span) {
    return pointsOf(buffer.decimate(series, t0, t1, qMax(1, columns)),
                    buffer.valueAt(series, t0 - 1), buffer.gaps().within(t0, t1), format, span);
}

ChartFrame buildFrame(const Telemetry &telemetry, const QList<ChartChannel> &channels,
                      const QList<ChartTrace> &traces, qint64 t0, qint64 t1, int columns) {
    ChartFrame frame;
    frame.t0 = t0;
    frame.t1 = t1;
    frame.points.resize(traces.size());
    // The traces of one channel share a buffer, and one decimation reads them all.
    QList<int> pending;
    for (int i = 0; i < traces.size(); ++i)
        pending.append(i);
    while (!pending.isEmpty()) {
        const int channel = traces.at(pending.constFirst()).channel;
        QList<int> group;
        for (int i : std::as_const(pending))
            if (traces.at(i).channel == channel)
                group.append(i);
        for (int i : std::as_const(group))
            pending.removeOne(i);
        const TelemetryBuffer *buffer = telemetry.buffer(channels.value(channel).key);
        if (!buffer)
            continue;
        QList<int> series;
        for (int i : std::as_const(group))
            series.append(buffer->seriesIndex(traces.at(i).series));
        // Block edges: a column's extremes are drawn at their true times, so a column edge moved
        // by a few samples changes no pixel, and the day window costs a quarter as much.
        const QList<QList<MinMaxBucket>> buckets =
            buffer->decimate(series, t0, t1, qMax(1, columns), ColumnEdges::Blocks);
        const QList<TelemetryGap> gaps = buffer->gaps().within(t0, t1);
        for (qsizetype g = 0; g < group.size(); ++g) {
            const ChartTrace &trace = traces.at(group.at(g));
            ValueSpan span;
            QList<QPointF> &points = frame.points[group.at(g)];
            points = pointsOf(buckets.at(g), buffer->valueAt(series.at(g), t0 - 1), gaps,
                              trace.format, &span);
            frame.pointCount += points.size();
            (trace.format.axis == ChartAxis::Left ? frame.left : frame.right).include(span);
        }
    }
    return frame;
}

QList<ReadoutValue> readoutAt(const Telemetry &telemetry, const QList<ChartChannel> &channels,
                              const QList<ChartTrace> &traces, qint64 timeMs) {
    QList<ReadoutValue> out;
    for (int i = 0; i < traces.size(); ++i) {
        ReadoutValue v;
        v.trace = i;
        const ChartTrace &trace = traces.at(i);
        if (const TelemetryBuffer *buffer = telemetry.buffer(channels.value(trace.channel).key)) {
            if (const auto s = buffer->valueAt(buffer->seriesIndex(trace.series), timeMs)) {
                v.valid = true;
                v.sampleMs = s->timeMs;
                v.wire = s->value;
                v.display = trace.format.toDisplay(s->value);
            }
        }
        out.append(v);
    }
    return out;
}

QStringList readoutCells(const QList<ChartTrace> &traces, const QList<ReadoutValue> &values) {
    QStringList cells;
    int channel = -1;
    for (const ReadoutValue &v : values) {
        const ChartTrace &t = traces.at(v.trace);
        const QString part = t.name + QLatin1Char(' ') +
                             (v.valid ? t.format.format(v.display) : QStringLiteral("—"));
        if (cells.isEmpty() || t.channel != channel)
            cells.append(part);
        else
            cells.last() += kReadoutJoin + part;
        channel = t.channel;
    }
    return cells;
}

QString readoutValuesText(const QList<ChartTrace> &traces, const QList<ReadoutValue> &values) {
    return readoutCells(traces, values).join(kReadoutJoin);
}

QString readoutTimeText(qint64 timeMs) {
    return QDateTime::fromMSecsSinceEpoch(timeMs).toString(QStringLiteral("HH:mm:ss.zzz"));
}

QString readoutText(const QList<ChartTrace> &traces, const QList<ReadoutValue> &values,
                    qint64 timeMs) {
    return readoutTimeText(timeMs) + QStringLiteral("   ") + readoutValuesText(traces, values);
}

ValueSpan niceRange(const ValueSpan &span, double minimumWidth) {
    if (!span.valid)
        return {0, minimumWidth, true};
    double low = span.min;
    double high = span.max;
    if (high - low < minimumWidth) {
        const double mid = (low + high) / 2;
        low = mid - minimumWidth / 2;
        high = mid + minimumWidth / 2;
    }
    // A step of about a fifth of the range, rounded to 1, 2 or 5 times a power of ten; a little
    // headroom keeps curves off the frame without pushing a room-temperature start below zero.
    const double raw = (high - low) / 5;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude * 10;
    for (double m : {1.0, 2.0, 5.0}) {
        if (magnitude * m >= raw) {
            step = magnitude * m;
            break;
        }
    }
    const double pad = (high - low) * 0.03;
    const double bottom = span.min >= 0 ? qMax(0.0, low - pad) : low - pad;
    return {std::floor(bottom / step) * step, std::ceil((high + pad) / step) * step, true};
}

} // namespace tipscope::model
