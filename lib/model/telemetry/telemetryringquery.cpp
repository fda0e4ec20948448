// Query side of TelemetryRing: time lookups, raw windows, decimation and window totals.
//
// Every query first turns times into sample numbers by binary search (times never decrease),
// then works on sample numbers; scanRange() is the one place that reads values, taking whole
// blocks from the summaries and only the ragged ends raw.
#include "telemetryring.h"

#include <algorithm>

namespace tipscope::model {

namespace {

// Raw reads stop at multiples of the finest block, where a summary can take over.
constexpr qint64 kFinestBlockMask = TelemetryRing::kFinestBlock - 1;

} // namespace

qint64 TelemetryRing::lowerBound(qint64 timeMs, qint64 from, qint64 to) const {
    while (from < to) {
        const qint64 mid = from + (to - from) / 2;
        if (timeAtIndex(mid) < timeMs)
            from = mid + 1;
        else
            to = mid;
    }
    return from;
}

qint64 TelemetryRing::upperBound(qint64 timeMs, qint64 from, qint64 to) const {
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
qint64 TelemetryRing::gallopLowerBound(qint64 timeMs, qint64 from, qint64 to) const {
    qint64 step = 1;
    while (from + step < to && timeAtIndex(from + step - 1) < timeMs) {
        from += step; // everything before the probe is earlier than timeMs
        step *= 2;
    }
    return lowerBound(timeMs, from, qMin(to, from + step));
}

std::optional<TelemetrySample> TelemetryRing::latestAt(int series, qint64 timeMs) const {
    if (series < 0 || series >= seriesCount() || isEmpty())
        return std::nullopt;
    const qint64 after = upperBound(timeMs, oldestIndex(), m_total);
    if (after == oldestIndex())
        return std::nullopt;
    const qint64 index = after - 1;
    return TelemetrySample{timeAtIndex(index), m_columns[size_t(series)].at(position(index))};
}

QList<TelemetrySample> TelemetryRing::samples(int series, qint64 t0, qint64 t1) const {
    QList<TelemetrySample> result;
    if (series < 0 || series >= seriesCount() || t1 <= t0)
        return result;
    const qint64 from = lowerBound(t0, oldestIndex(), m_total);
    const qint64 to = lowerBound(t1, from, m_total);
    result.reserve(qsizetype(to - from));
    const Values &column = m_columns[size_t(series)];
    for (qint64 index = from; index < to; ++index) {
        const qsizetype pos = position(index);
        result.append(TelemetrySample{m_times[size_t(pos)], column.at(pos)});
    }
    return result;
}

// Unsigned arithmetic: the span of any two qint64 times fits, and edge k is exactly
// t0 + span * k / buckets without the product overflowing.
qint64 TelemetryRing::columnStart(qint64 t0, qint64 t1, int buckets, int column) {
    const quint64 span = quint64(t1) - quint64(t0);
    const quint64 step = span / quint64(buckets);
    const quint64 rest = span % quint64(buckets);
    return qint64(quint64(t0) + step * quint64(column) + rest * quint64(column) / quint64(buckets));
}

std::vector<TelemetryRing::ColumnRange>
TelemetryRing::columnRanges(qint64 t0, qint64 t1, int buckets, ColumnEdges edges) const {
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

TelemetryRing::Extreme TelemetryRing::extremeOf(const Pick &pick, qint64 first, qint64 last) const {
    const Extremes low = scanRange(pick.minSeries, first, last);
    const Extremes high =
        pick.maxSeries == pick.minSeries ? low : scanRange(pick.maxSeries, first, last);
    return Extreme{timeAtIndex(low.minIndex), low.min, timeAtIndex(high.maxIndex), high.max};
}

qint64 TelemetryRing::countOf(int countSeries, qint64 first, qint64 last) const {
    return countSeries == kCountEntries ? last - first : scanRange(countSeries, first, last).sum;
}

std::vector<TelemetryRing::Column> TelemetryRing::columns(const std::vector<Pick> &picks,
                                                          int countSeries, qint64 t0, qint64 t1,
                                                          int buckets, ColumnEdges edges) const {
    const std::vector<ColumnRange> ranges = columnRanges(t0, t1, buckets, edges);
    std::vector<Column> result;
    result.reserve(ranges.size());
    // Column by column, all series at once: the summaries of one block keep the series side by
    // side, so one cache line serves them all (series by series was twice as slow).
    for (const ColumnRange &r : ranges) {
        Column column{r.column, countOf(countSeries, r.first, r.last), {}};
        column.extremes.reserve(picks.size());
        for (const Pick &pick : picks)
            column.extremes.push_back(extremeOf(pick, r.first, r.last));
        result.push_back(std::move(column));
    }
    return result;
}

TelemetryRing::Totals TelemetryRing::totals(const Pick &pick, int sumSeries, int countSeries,
                                            qint64 t0, qint64 t1) const {
    if (t1 <= t0 || isEmpty())
        return {};
    const qint64 from = lowerBound(t0, oldestIndex(), m_total);
    const qint64 to = lowerBound(t1, from, m_total);
    if (from == to)
        return {};
    const Extreme e = extremeOf(pick, from, to);
    return Totals{e.min, e.max, scanRange(sumSeries, from, to).sum, countOf(countSeries, from, to)};
}

TelemetryRing::Extremes TelemetryRing::scanRange(int series, qint64 first, qint64 last) const {
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

void TelemetryRing::scanRaw(int series, qint64 first, qint64 last, Extremes &result) const {
    const Values &column = m_columns[size_t(series)];
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

void TelemetryRing::Values::scan(qsizetype pos, qsizetype count, qint64 firstIndex,
                                 Extremes &result) const {
    if (m_isWide)
        scanValues(m_wide.data() + pos, count, firstIndex, result);
    else
        scanValues(m_narrow.data() + pos, count, firstIndex, result);
}

// The coarsest block that starts at `index` and ends by `last`. Callers only pass ranges of
// held samples, so such a block is complete and its slot has not been reused.
const TelemetryRing::Level *TelemetryRing::wholeBlockAt(qint64 index, qint64 last) const {
    for (auto level = m_levels.rbegin(); level != m_levels.rend(); ++level) {
        const qint64 blockSize = qint64(1) << level->shift;
        if ((index & (blockSize - 1)) == 0 && last - index >= blockSize)
            return &*level;
    }
    return nullptr;
}

} // namespace tipscope::model
