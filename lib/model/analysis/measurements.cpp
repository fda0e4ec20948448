#include "model/analysis/measurements.h"

#include "model/device/portmodel.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace tipscope::model {

namespace {
// Columns used to locate changes and crossings; only columns that can hold one are read raw.
constexpr int kSearchColumns = 256;

// The end of bucket `i`: the next non-empty bucket's start (the ones between hold nothing).
qint64 bucketEnd(const QList<MinMaxBucket> &buckets, qsizetype i, qint64 t1) {
    return i + 1 < buckets.size() ? buckets.at(i + 1).startMs : t1;
}

// The first sample of [t0, t1) matching `wanted`, reading raw only the columns `mayHold` admits.
template <class MayHold, class Wanted>
std::optional<qint64> firstMatch(const TelemetryBuffer &buffer, int series, qint64 t0, qint64 t1,
                                 MayHold mayHold, Wanted wanted) {
    const QList<MinMaxBucket> buckets = buffer.decimate(series, t0, t1, kSearchColumns);
    for (qsizetype i = 0; i < buckets.size(); ++i) {
        if (!mayHold(buckets.at(i)))
            continue;
        const auto samples =
            buffer.samples(series, buckets.at(i).startMs, bucketEnd(buckets, i, t1));
        for (const TelemetryBuffer::Sample &s : samples)
            if (s.timeMs >= t0 && wanted(s.value))
                return s.timeMs;
    }
    return std::nullopt;
}

bool isWorking(const TelemetryBuffer &buffer, int status, qint64 timeMs) {
    const auto s = buffer.valueAt(status, timeMs);
    if (!s)
        return false;
    const PortStatus p = PortStatus::fromNumber(s->value);
    return p.mode == PortStatus::Mode::Working && !p.cooling;
}

// The status and the setpoint are read less often than the tip (the scheduler reads them at
// once only when the tip turns), so the flag of a wake or a new setpoint may come after the tip
// began to move. The heat-up starts where the tip's climb (or fall) toward the target began: the
// last sample at or before the flag from which the tip moved that way all along, but for a
// reading's wobble, looked for no further back than kLookBackMs nor before `from`. A move smaller
// than the band is no climb: the flag's time stands.
constexpr qint64 kLookBackMs = 30'000;
constexpr qint32 kWobble = 1;

qint64 climbStart(const TelemetryBuffer &buffer, int tip, qint64 from, qint64 flagMs, bool up,
                  qint32 tolerance) {
    const QList<TelemetryBuffer::Sample> s =
        buffer.samples(tip, qMax(from, flagMs - kLookBackMs), flagMs + 1);
    if (s.isEmpty())
        return flagMs;
    const qint32 atFlag = s.last().value;
    qint32 extreme = atFlag;
    qsizetype first = s.size() - 1; // the earliest sample of the climb and its plateau's wobble
    for (qsizetype i = s.size() - 1; i >= 0; --i) {
        const qint32 v = s.at(i).value;
        if (up ? v > extreme + kWobble : v < extreme - kWobble)
            break;
        extreme = up ? qMin(extreme, v) : qMax(extreme, v);
        first = i;
    }
    if (std::abs(atFlag - extreme) < tolerance)
        return flagMs;
    // The plateau's last reading: the climb left it right after.
    qint64 foot = s.at(first).timeMs;
    for (qsizetype i = first; i < s.size(); ++i)
        if (std::abs(s.at(i).value - extreme) <= kWobble)
            foot = s.at(i).timeMs;
    return qMin(foot, flagMs);
}

bool wasResting(const TelemetryBuffer &buffer, int status, qint64 timeMs) {
    const auto s = buffer.valueAt(status, timeMs - 1);
    if (!s)
        return false;
    const PortStatus::Mode m = PortStatus::fromNumber(s->value).mode;
    return m == PortStatus::Mode::Sleep || m == PortStatus::Mode::Hibernation;
}
} // namespace

QList<qint64> Measurements::changeTimes(const TelemetryBuffer &buffer, int series, qint64 t0,
                                        qint64 t1, int maxChanges) {
    QList<qint64> out;
    std::optional<qint32> previous;
    if (const auto lead = buffer.valueAt(series, t0 - 1))
        previous = lead->value;
    const QList<MinMaxBucket> buckets = buffer.decimate(series, t0, t1, kSearchColumns);
    for (qsizetype i = 0; i < buckets.size() && out.size() < maxChanges; ++i) {
        const MinMaxBucket &b = buckets.at(i);
        if (b.min == b.max) {
            // A constant column: only its first sample can be a change.
            if (previous && *previous != b.min)
                out.append(b.minTimeMs);
            previous = b.min;
            continue;
        }
        for (const auto &s : buffer.samples(series, b.startMs, bucketEnd(buckets, i, t1))) {
            if (previous && *previous != s.value)
                out.append(s.timeMs);
            previous = s.value;
        }
    }
    return out;
}

std::optional<qint64> Measurements::firstWithin(const TelemetryBuffer &buffer, int series,
                                                qint64 t0, qint64 t1, qint32 low, qint32 high) {
    return firstMatch(
        buffer, series, t0, t1,
        [&](const MinMaxBucket &b) { return b.max >= low && b.min <= high; },
        [&](qint32 v) { return v >= low && v <= high; });
}

std::optional<qint64> Measurements::firstBelow(const TelemetryBuffer &buffer, int series, qint64 t0,
                                               qint64 t1, qint32 limit) {
    return firstMatch(
        buffer, series, t0, t1, [&](const MinMaxBucket &b) { return b.min < limit; },
        [&](qint32 v) { return v < limit; });
}

PortMeasurements Measurements::measurePort(const TelemetryBuffer &buffer, qint64 t0, qint64 t1,
                                           qint32 tolerance, int maxResults) {
    // Nothing was measured in a gap: a heat-up or a dip that meets one has no end, and the first
    // samples after it are no change from the last ones before.
    PortMeasurements out;
    for (const auto &[from, to] : buffer.gaps().continuousStretches(t0, t1)) {
        const PortMeasurements part = measureStretch(buffer, from, to, tolerance, maxResults);
        const auto keep = [&](auto &into, const auto &from) {
            for (const auto &m : from) {
                if (into.size() < maxResults)
                    into.append(m);
                else
                    out.truncated = true;
            }
        };
        keep(out.heatUps, part.heatUps);
        keep(out.recoveries, part.recoveries);
        out.truncated = out.truncated || part.truncated;
    }
    return out;
}

PortMeasurements Measurements::measureStretch(const TelemetryBuffer &buffer, qint64 t0, qint64 t1,
                                              qint32 tolerance, int maxResults) {
    PortMeasurements out;
    const int tip = buffer.seriesIndex(QStringLiteral("tip"));
    const int setpoint = buffer.seriesIndex(QStringLiteral("setpoint"));
    const int status = buffer.seriesIndex(QStringLiteral("status"));
    const int power = buffer.seriesIndex(QStringLiteral("power"));
    if (tip < 0 || setpoint < 0 || status < 0 || buffer.size() == 0)
        return out;
    // A window reaching back before the first sample (any window early in a session) is measured
    // from that sample: at t0 itself there would be no setpoint to measure against. Older history
    // of a tiered buffer is only summaries, where no change or crossing can be timed: measured
    // from where the full-rate samples start.
    t0 = qMax(t0, buffer.fullRateFrom());
    if (t1 <= t0)
        return out;
    // A tip cooling with the heater off (no tool, a port error) is no dip to recover from. Under
    // a joint the heater is at work where the tip is lowest and until it is back; with the heater
    // off, the power reads 0 there. Either end of the dip alone could mislead: power and tip are
    // read one after the other, so the first sample of a joint may still carry an idle 0 and the
    // first samples after a tool is pulled the power it had.
    const auto heated = [&](qint64 lowestMs, qint64 lastMs) {
        if (power < 0)
            return true;
        const auto atLowest = buffer.valueAt(power, lowestMs);
        const auto atLast = buffer.valueAt(power, lastMs);
        return (atLowest && atLowest->value > 0) || (atLast && atLast->value > 0);
    };

    // The window splits into segments of one setpoint and one status.
    const int maxChanges = int(qMin<qint64>(4LL * maxResults, std::numeric_limits<int>::max()));
    const QList<qint64> setpointChanges = changeTimes(buffer, setpoint, t0, t1, maxChanges);
    QList<qint64> edges = setpointChanges + changeTimes(buffer, status, t0, t1, maxChanges);
    edges.append(t0);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    for (qsizetype i = 0; i < edges.size(); ++i) {
        const qint64 start = edges.at(i);
        const qint64 end = i + 1 < edges.size() ? edges.at(i + 1) : t1;
        // The session records 0 for a setpoint not read yet: no target, and no "change" from it.
        const auto target = buffer.valueAt(setpoint, start);
        if (!target || target->value <= 0 || !isWorking(buffer, status, start))
            continue;
        const qint32 low = target->value - tolerance;
        const qint32 high = target->value + tolerance;
        const auto before = buffer.valueAt(setpoint, start - 1);
        const bool newSetpoint = setpointChanges.contains(start) && before && before->value > 0;
        const bool wake = !newSetpoint && start != t0 && wasResting(buffer, status, start);
        const qint64 climb = newSetpoint || wake
                                 ? climbStart(buffer, tip, i > 0 ? edges.at(i - 1) : t0, start,
                                              wake || target->value > before->value, tolerance)
                                 : start;
        const auto settled = firstWithin(buffer, tip, climb, end, low, high);
        if (newSetpoint || wake) {
            if (out.heatUps.size() < maxResults)
                out.heatUps.append(HeatUp{climb, target->value, wake, settled});
            else
                out.truncated = true;
        }
        // Dips count only once the tip has settled at this setpoint.
        for (auto from = settled; from;) {
            const auto dip = firstBelow(buffer, tip, *from, end, low);
            if (!dip)
                break;
            const auto back = firstWithin(buffer, tip, *dip, end, low, high);
            const QList<MinMaxBucket> whole = buffer.decimate(tip, *dip, back.value_or(end), 1);
            if (out.recoveries.size() >= maxResults || whole.isEmpty()) {
                out.truncated = out.truncated || !whole.isEmpty();
                break;
            }
            if (heated(whole.first().minTimeMs, back.value_or(end) - 1))
                out.recoveries.append(Recovery{*dip, target->value, whole.first().min,
                                               whole.first().minTimeMs, back});
            from = back;
        }
    }
    return out;
}

} // namespace tipscope::model
