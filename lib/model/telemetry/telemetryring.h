// TelemetryRing: the full-rate sample store under TelemetryBuffer (which adds gaps, the older
// tier of summaries and the public API); both tiers of a buffer are rings.
//
// The number of series is fixed at construction; each sample is one timestamp (ms since the
// epoch) with one integer per series, in wire units. The caller appends in non-decreasing time
// with exactly one value per series (TelemetryBuffer checks both), so every query can
// binary-search on time. When `capacity()` samples are held, each new sample overwrites the
// oldest; dropOldest() lets samples go earlier (folded into summaries by the caller). Storage
// grows with the history up to the capacity, so a short session does not pay for a whole day.
//
// Memory: one qint64 per sample for the time, one int16 per series and sample (a column widens
// to int32 for good the first time a value needs it, so no value is ever clipped), and summaries
// of min, max and sum per block of 64, 4096 and 262144 samples (the levels the capacity can
// hold). For a day-sized ring that is about 4.4 bytes per sample per series with four int16
// series and 12.4 at worst (one int32 series), plus a few hundred bytes of fixed overhead;
// `memoryBytes()` counts the real allocation.
//
// Queries: columns() gives min and max per time column for a chart, exact (a one-sample spike
// is never lost), at a cost set by the number of columns rather than the length of the history:
// raw samples are only read at column edges, the rest comes from the block summaries. Summaries
// are indexed by absolute sample number, so overwriting needs no repair: a block that has lost
// samples to the ring is never used whole, its surviving samples are read raw instead. A query
// names the column it reads the minimum from, the one it reads the maximum from and the one it
// counts samples with, so the same code answers for raw samples (all three the series itself,
// counting entries) and for summaries (a min, a max and a count column).
//
// Time windows are half-open, [t0, t1). Not thread-safe.
#pragma once

#include <QList>
#include <QtGlobal>
#include <optional>
#include <vector>

namespace tipscope::model {

// Where the edges between the columns of a decimated window go.
enum class ColumnEdges {
    // Exactly on the time grid: [t0, t1) split into equal columns. Raw samples are read at every
    // edge, which on a long window costs a cache miss per edge and series.
    Exact,
    // For a chart of a long window: when a column holds at least kSnapMinBlocks of the finest
    // summary blocks, each inner edge moves to the nearest block boundary (at most 32 samples,
    // well under a column), so whole columns come from the summaries. Every sample still falls
    // in exactly one column and each column's min and max are exact for the samples it holds,
    // at their true times: a spike is never lost, it may be counted one column over.
    Blocks,
};

struct TelemetrySample {
    qint64 timeMs = 0;
    qint32 value = 0;
};

class TelemetryRing {
public:
    // Samples per block of the finest summary level.
    static constexpr int kFinestBlock = 64;
    // ColumnEdges::Blocks moves edges only when a column holds this many finest blocks.
    static constexpr int kSnapMinBlocks = 4;

    // Which columns a query reads: the minimum from `minSeries`, the maximum from `maxSeries`.
    struct Pick {
        int minSeries = 0;
        int maxSeries = 0;
    };
    // The extremes of one pick over one column or window, each at the time of the earliest
    // entry holding it.
    struct Extreme {
        qint64 minTimeMs = 0;
        qint32 min = 0;
        qint64 maxTimeMs = 0;
        qint32 max = 0;
    };
    // One non-empty time column: its index in the grid, the samples it counts and one Extreme
    // per pick.
    struct Column {
        int column = 0;
        qint64 count = 0;
        std::vector<Extreme> extremes;
    };
    // Over a window: extremes of `minSeries`/`maxSeries`, the sum of `sumSeries`, and the count.
    struct Totals {
        qint32 min = 0;
        qint32 max = 0;
        qint64 sum = 0;
        qint64 count = 0; // 0 for an empty window; the other fields are then 0
    };
    // A query's count: the number of entries (-1) or the sum of a count series.
    static constexpr int kCountEntries = -1;

    TelemetryRing(int seriesCount, int capacity);

    [[nodiscard]] int seriesCount() const { return int(m_columns.size()); }
    [[nodiscard]] int capacity() const { return m_capacity; }
    [[nodiscard]] int size() const { return int(m_total - oldestIndex()); }
    [[nodiscard]] bool isEmpty() const { return size() == 0; }
    // Both 0 when empty.
    [[nodiscard]] qint64 firstTime() const { return isEmpty() ? 0 : timeAtIndex(oldestIndex()); }
    [[nodiscard]] qint64 lastTime() const { return m_lastTime; }

    // `values` holds one value per series; the time must not be older than lastTime().
    void append(qint64 timeMs, const qint32 *values);
    // The `count` oldest held samples are no longer held (a caller folded them elsewhere).
    void dropOldest(qint64 count);

    // The i-th held sample, 0 the oldest.
    [[nodiscard]] qint64 timeAt(int i) const { return timeAtIndex(oldestIndex() + i); }
    [[nodiscard]] qint32 valueAt(int series, int i) const {
        return m_columns[size_t(series)].at(position(oldestIndex() + i));
    }
    // Number of held samples older than `timeMs`.
    [[nodiscard]] int countBefore(qint64 timeMs) const {
        return int(lowerBound(timeMs, oldestIndex(), m_total) - oldestIndex());
    }

    // The newest sample at or before `timeMs`; nullopt if there is none.
    [[nodiscard]] std::optional<TelemetrySample> latestAt(int series, qint64 timeMs) const;
    // Every sample of [t0, t1), oldest first.
    [[nodiscard]] QList<TelemetrySample> samples(int series, qint64 t0, qint64 t1) const;
    // [t0, t1) split into `buckets` equal time columns; empty columns are left out.
    [[nodiscard]] std::vector<Column> columns(const std::vector<Pick> &picks, int countSeries,
                                              qint64 t0, qint64 t1, int buckets,
                                              ColumnEdges edges) const;
    [[nodiscard]] Totals totals(const Pick &pick, int sumSeries, int countSeries, qint64 t0,
                                qint64 t1) const;
    // Start of column `column` of [t0, t1) split into `buckets`.
    [[nodiscard]] static qint64 columnStart(qint64 t0, qint64 t1, int buckets, int column);

    // Heap bytes allocated for samples and summaries plus the object itself.
    [[nodiscard]] qint64 memoryBytes() const;
    // Sample slots allocated so far (at most the capacity).
    [[nodiscard]] qint64 allocatedSlots() const { return qint64(m_times.capacity()); }

private:
    struct Extremes;

    // One series' values by ring position: int16 until a value does not fit, then int32.
    class Values {
    public:
        [[nodiscard]] qint32 at(qsizetype pos) const {
            return m_isWide ? m_wide[size_t(pos)] : qint32(m_narrow[size_t(pos)]);
        }
        void store(qsizetype pos, qint32 value);
        // Folds `count` values from ring position `pos` (not wrapping), the first of which is
        // sample number `firstIndex`, into `result`.
        void scan(qsizetype pos, qsizetype count, qint64 firstIndex, Extremes &result) const;
        void reserve(qsizetype slots);
        [[nodiscard]] qint64 bytes() const;

    private:
        void widen();

        std::vector<qint16> m_narrow;
        std::vector<qint32> m_wide;
        bool m_isWide = false;
    };

    // Offsets are within the block, so the earliest extreme's sample number is start + offset.
    struct Summary {
        qint64 sum = 0;
        qint32 min = 0;
        qint32 max = 0;
        quint32 minOffset = 0;
        quint32 maxOffset = 0;
    };

    // Blocks of 1 << shift samples; block b lives in slot b % slots, entry slot * series + s.
    struct Level {
        int shift = 0;
        qint64 slots = 0;
        std::vector<Summary> summaries;
    };

    struct Extremes {
        qint64 minIndex = -1;
        qint64 maxIndex = -1;
        qint32 min = 0;
        qint32 max = 0;
        qint64 sum = 0;
    };

    // Ring position of a held sample. Cheaper than index % capacity, which dominated the binary
    // searches: a held sample is either in the current lap of the ring or in the previous one.
    [[nodiscard]] qsizetype position(qint64 index) const {
        return qsizetype(index >= m_lapStart ? index - m_lapStart
                                             : index - m_lapStart + m_capacity);
    }
    [[nodiscard]] qint64 timeAtIndex(qint64 index) const {
        return m_times[size_t(position(index))];
    }
    [[nodiscard]] qint64 oldestIndex() const {
        return qMax(m_total - qMin<qint64>(m_total, m_capacity), m_dropped);
    }

    void growStorage();
    void updateSummaries(qint64 index, const qint32 *values);
    // First sample number in [from, to) whose time is >= timeMs (or > timeMs), else `to`.
    [[nodiscard]] qint64 lowerBound(qint64 timeMs, qint64 from, qint64 to) const;
    [[nodiscard]] qint64 upperBound(qint64 timeMs, qint64 from, qint64 to) const;
    // lowerBound() for an answer expected close to `from`.
    [[nodiscard]] qint64 gallopLowerBound(qint64 timeMs, qint64 from, qint64 to) const;
    // Exact extremes and sum of the held samples [first, last), which must not be empty.
    [[nodiscard]] Extremes scanRange(int series, qint64 first, qint64 last) const;
    void scanRaw(int series, qint64 first, qint64 last, Extremes &result) const;
    [[nodiscard]] const Level *wholeBlockAt(qint64 index, qint64 last) const;
    [[nodiscard]] qint64 countOf(int countSeries, qint64 first, qint64 last) const;
    [[nodiscard]] Extreme extremeOf(const Pick &pick, qint64 first, qint64 last) const;
    // The sample numbers [first, last) of each non-empty column of columns(), with the column.
    struct ColumnRange {
        int column = 0;
        qint64 first = 0;
        qint64 last = 0;
    };
    [[nodiscard]] std::vector<ColumnRange> columnRanges(qint64 t0, qint64 t1, int buckets,
                                                        ColumnEdges edges) const;

    int m_capacity;
    qint64 m_total = 0;    // samples ever appended; sample n sits at ring position n % capacity
    qint64 m_lapStart = 0; // the sample number at ring position 0 in the current lap
    qint64 m_dropped = 0;  // samples numbered below this were dropped by dropOldest()
    qint64 m_lastTime = 0;
    std::vector<qint64> m_times;
    std::vector<Values> m_columns;
    std::vector<Level> m_levels;
};

} // namespace tipscope::model
