// Query side of TelemetryBuffer: time lookups, raw windows, decimation and window statistics.
//
// Every query first turns times into sample numbers by binary search (times never decrease),
// then works on sample numbers; scanRange() is the one place that reads values, taking whole
// blocks from the summaries and only the ragged ends raw.
#include "telemetrybuffer.h"

#include <algorithm>

namespace tipscope::model {

namespace {

// Raw reads stop at multiples of the finest block, where a summary can take over.
constexpr qint64 kFinestBlockMask = TelemetryBuffer::kFinestBlock - 1;

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
    if (!isSeries(series) || isEmpty() || m_gaps.at(timeMs))
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

// Unsigned arithmetic: the span of any two qint64 times fits, and edge k is exactly
// t0 + span * k / buckets without the product overflowing.
qint64 TelemetryBuffer::columnStart(qint64 t0, qint64 t1, int buckets, int column) {
    const quint64 span = quint64(t1) - quint64(t0);
    const quint64 step = span / quint64(buckets);
    const quint64 rest = span % quint64(buckets);
    return qint64(quint64(t0) + step * quint64(column) + rest * quint64(column) / quint64(buckets));
}

std::vector<TelemetryBuffer::ColumnRange>
TelemetryBuffer::columnRanges(qint64 t0, qint64 t1, int buckets, ColumnEdges edges) const {
    std::vector<ColumnRange> ranges;
    if (isEmpty() || t1 <= t0 || buckets <= 0)
        return ranges;
    qint64 from = lowerBound(t0, oldestIndex(), m_total);
    const qint64 end = lowerBound(t1, from, m_total);
    ranges.reserve(size_t(qMin<qint64>(buckets, end - from)));
    const bool snap = edges == ColumnEdges::Blocks &&
                      (end - from) / buckets >= qint64(kSnapMinBlocks) * kFinestBlock;
    for (int k = 0; k < buckets && from < end; ++k) {
        const qint64 columnEnd = k + 1 == buckets ? t1 : columnStart(t0, t1, buckets, k + 1);
        qint64 to = gallopLowerBound(columnEnd, from, end);
        if (snap && k + 1 < buckets) // the last edge is the window's, never moved
            to = qBound(from, (to + kFinestBlock / 2) & ~kFinestBlockMask, end);
        if (to > from)
            ranges.push_back({k, from, to});
        from = to;
    }
    return ranges;
}

QList<MinMaxBucket> TelemetryBuffer::decimate(int series, qint64 t0, qint64 t1, int buckets) const {
    return decimate(QList<int>{series}, t0, t1, buckets).constFirst();
}

QList<QList<MinMaxBucket>> TelemetryBuffer::decimate(const QList<int> &series, qint64 t0, qint64 t1,
                                                     int buckets, ColumnEdges edges) const {
    QList<QList<MinMaxBucket>> result(series.size());
    const std::vector<ColumnRange> ranges = columnRanges(t0, t1, buckets, edges);
    for (qsizetype i = 0; i < series.size(); ++i)
        if (isSeries(series.at(i)))
            result[i].reserve(qsizetype(ranges.size()));
    // Column by column, all series at once: the summaries of one block keep the series side by
    // side, so one cache line serves them all (series by series was twice as slow).
    for (const ColumnRange &r : ranges) {
        const qint64 start = columnStart(t0, t1, buckets, r.column);
        for (qsizetype i = 0; i < series.size(); ++i) {
            if (!isSeries(series.at(i)))
                continue;
            const Extremes e = scanRange(series.at(i), r.first, r.last);
            result[i].append(MinMaxBucket{start, timeAtIndex(e.minIndex), e.min,
                                          timeAtIndex(e.maxIndex), e.max, int(r.last - r.first)});
        }
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
    // At most two contiguous pieces: up to the end of the ring, then from its start.
    const qsizetype pos = position(first);
    const qsizetype count = qsizetype(last - first);
    const qsizetype head = qMin<qsizetype>(count, qsizetype(m_capacity) - pos);
    column.scan(pos, head, first, result);
    if (head < count)
        column.scan(0, count - head, first + head, result);
}

namespace {

// Two passes over a few dozen values: a branch-free min/max/sum the compiler can vectorise, then
// the first position of each extreme, only when it beats the one already held (the earliest
// extreme wins, as in the summaries).
template <typename T, typename Extremes>
void scanValues(const T *values, qsizetype count, qint64 firstIndex, Extremes &r) {
    if (count <= 0)
        return;
    T low = values[0];
    T high = values[0];
    qint64 sum = 0;
    for (qsizetype i = 0; i < count; ++i) {
        low = std::min(low, values[i]);
        high = std::max(high, values[i]);
        sum += values[i];
    }
    if (r.minIndex < 0 || qint32(low) < r.min) {
        r.min = low;
        r.minIndex = firstIndex + (std::find(values, values + count, low) - values);
    }
    if (r.maxIndex < 0 || qint32(high) > r.max) {
        r.max = high;
        r.maxIndex = firstIndex + (std::find(values, values + count, high) - values);
    }
    r.sum += sum;
}

} // namespace

void TelemetryBuffer::Column::scan(qsizetype pos, qsizetype count, qint64 firstIndex,
                                   Extremes &result) const {
    if (m_isWide)
        scanValues(m_wide.data() + pos, count, firstIndex, result);
    else
        scanValues(m_narrow.data() + pos, count, firstIndex, result);
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
