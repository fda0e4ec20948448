// Query side of TelemetryBuffer: time lookups, raw windows, decimation and window statistics.
//
// Every query first turns times into sample numbers by binary search (times never decrease),
// then works on sample numbers; scanRange() is the one place that reads values, taking whole
// blocks from the summaries and only the ragged ends raw.
#include "telemetrybuffer.h"

namespace tipscope::model {

namespace {

// Raw reads stop at multiples of the finest block, where a summary can take over.
constexpr qint64 kFinestBlockMask = 63;

} // namespace

qint64 TelemetryBuffer::lowerBound(qint64 timeMs, qint64 from, qint64 to) const {
    while (from < to) {
        const qint64 mid = from + (to - from) / 2;
        if (timeAtIndex(mid) < timeMs)
            from = mid + 1;
        else
            to = mid;
    }
    return from;
}

qint64 TelemetryBuffer::upperBound(qint64 timeMs, qint64 from, qint64 to) const {
    while (from < to) {
        const qint64 mid = from + (to - from) / 2;
        if (timeAtIndex(mid) <= timeMs)
            from = mid + 1;
        else
            to = mid;
    }
    return from;
}

// The next bucket edge is usually a few hundred samples past the previous one: probing doubling
// steps from there stays within cache lines already fetched, where a bisection of the whole
// history would miss the cache on most of its first probes.
qint64 TelemetryBuffer::gallopLowerBound(qint64 timeMs, qint64 from, qint64 to) const {
    qint64 step = 1;
    while (from + step < to && timeAtIndex(from + step - 1) < timeMs) {
        from += step; // everything before the probe is earlier than timeMs
        step *= 2;
    }
    return lowerBound(timeMs, from, qMin(to, from + step));
}

std::optional<TelemetryBuffer::Sample> TelemetryBuffer::valueAt(int series, qint64 timeMs) const {
    if (!isSeries(series) || isEmpty())
        return std::nullopt;
    const qint64 after = upperBound(timeMs, oldestIndex(), m_total);
    if (after == oldestIndex())
        return std::nullopt;
    const qint64 index = after - 1;
    return Sample{timeAtIndex(index), m_columns[size_t(series)].at(position(index))};
}

QList<TelemetryBuffer::Sample> TelemetryBuffer::samples(int series, qint64 t0, qint64 t1) const {
    QList<Sample> result;
    if (!isSeries(series) || t1 <= t0)
        return result;
    const qint64 from = lowerBound(t0, oldestIndex(), m_total);
    const qint64 to = lowerBound(t1, from, m_total);
    result.reserve(qsizetype(to - from));
    const Column &column = m_columns[size_t(series)];
    for (qint64 index = from; index < to; ++index) {
        const qsizetype pos = position(index);
        result.append(Sample{m_times[size_t(pos)], column.at(pos)});
    }
    return result;
}

QList<MinMaxBucket> TelemetryBuffer::decimate(int series, qint64 t0, qint64 t1, int buckets) const {
    QList<MinMaxBucket> result;
    if (!isSeries(series) || t1 <= t0 || buckets <= 0)
        return result;
    qint64 from = lowerBound(t0, oldestIndex(), m_total);
    const qint64 end = lowerBound(t1, from, m_total);
    if (from == end)
        return result;

    // Unsigned arithmetic: the span of any two qint64 times fits, and edge k is exactly
    // t0 + span * k / buckets without the product overflowing.
    const quint64 span = quint64(t1) - quint64(t0);
    const quint64 step = span / quint64(buckets);
    const quint64 rest = span % quint64(buckets);
    const auto edge = [&](int k) {
        return qint64(quint64(t0) + step * quint64(k) + rest * quint64(k) / quint64(buckets));
    };

    result.reserve(qsizetype(qMin<qint64>(buckets, end - from)));
    for (int k = 0; k < buckets && from < end; ++k) {
        const qint64 bucketEnd = k + 1 == buckets ? t1 : edge(k + 1);
        const qint64 to = gallopLowerBound(bucketEnd, from, end);
        if (to > from) {
            const Extremes e = scanRange(series, from, to);
            result.append(MinMaxBucket{edge(k), timeAtIndex(e.minIndex), e.min,
                                       timeAtIndex(e.maxIndex), e.max, int(to - from)});
        }
        from = to;
    }
    return result;
}

TelemetryBuffer::Stats TelemetryBuffer::windowStats(int series, qint64 t0, qint64 t1) const {
    if (!isSeries(series) || t1 <= t0)
        return {};
    const qint64 from = lowerBound(t0, oldestIndex(), m_total);
    const qint64 to = lowerBound(t1, from, m_total);
    if (from == to)
        return {};
    const Extremes e = scanRange(series, from, to);
    const qint64 count = to - from;
    return Stats{e.min, e.max, double(e.sum) / double(count), count};
}

TelemetryBuffer::Extremes TelemetryBuffer::scanRange(int series, qint64 first, qint64 last) const {
    Extremes result;
    const auto seriesCount = size_t(m_columns.size());
    qint64 index = first;
    while (index < last) {
        const Level *level = wholeBlockAt(index, last);
        if (!level) {
            const qint64 stop = qMin(last, (index | kFinestBlockMask) + 1);
            scanRaw(series, index, stop, result);
            index = stop;
            continue;
        }
        const qint64 block = index >> level->shift;
        const Summary &s =
            level->summaries[size_t(block % level->slots) * seriesCount + size_t(series)];
        // Blocks are merged oldest first with strict comparisons: the earliest extreme wins.
        if (result.minIndex < 0 || s.min < result.min) {
            result.min = s.min;
            result.minIndex = index + s.minOffset;
        }
        if (result.maxIndex < 0 || s.max > result.max) {
            result.max = s.max;
            result.maxIndex = index + s.maxOffset;
        }
        result.sum += s.sum;
        index += qint64(1) << level->shift;
    }
    return result;
}

void TelemetryBuffer::scanRaw(int series, qint64 first, qint64 last, Extremes &result) const {
    const Column &column = m_columns[size_t(series)];
    // A local copy: writing through the reference each sample would force it out to memory.
    Extremes r = result;
    qsizetype pos = position(first);
    for (qint64 index = first; index < last; ++index) {
        const qint32 value = column.at(pos);
        if (r.minIndex < 0 || value < r.min) {
            r.min = value;
            r.minIndex = index;
        }
        if (r.maxIndex < 0 || value > r.max) {
            r.max = value;
            r.maxIndex = index;
        }
        r.sum += value;
        if (++pos == m_capacity)
            pos = 0;
    }
    result = r;
}

// The coarsest block that starts at `index` and ends by `last`. Callers only pass ranges of
// held samples, so such a block is complete and its slot has not been reused.
const TelemetryBuffer::Level *TelemetryBuffer::wholeBlockAt(qint64 index, qint64 last) const {
    for (auto level = m_levels.rbegin(); level != m_levels.rend(); ++level) {
        const qint64 blockSize = qint64(1) << level->shift;
        if ((index & (blockSize - 1)) == 0 && last - index >= blockSize)
            return &*level;
    }
    return nullptr;
}

} // namespace tipscope::model
