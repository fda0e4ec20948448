// TelemetryBuffer: the sample history of one port (or one feeder), kept in a compact ring.
//
// The series (for example "tip", "setpoint", "power", "status") are fixed at construction; each
// sample is one timestamp (ms since the epoch) with one integer per series, in wire units. Samples
// must arrive in non-decreasing time: an older one is refused and counted, never inserted, so
// every query can binary-search on time. When `capacity()` samples are held, each new sample
// overwrites the oldest. Storage grows with the history up to the capacity, so a short session
// does not pay for a whole day.
//
// Memory: one qint64 per sample for the time, one int16 per series and sample (a column widens
// to int32 for good the first time a value needs it, so no value is ever clipped), and summaries
// of min, max and sum per block of 64, 4096 and 262144 samples (the levels the capacity can
// hold). For a day-sized buffer that is about 4.4 bytes per sample per series with four int16
// series and 12.4 at worst (one int32 series), plus a few hundred bytes of fixed overhead;
// `memoryBytes()` counts the real allocation.
//
// Queries: `decimate()` gives min and max per time column for a chart, exact (a one-sample spike
// is never lost), at a cost set by the number of buckets rather than the length of the history:
// raw samples are only read at bucket edges, the rest comes from the block summaries. Summaries
// are indexed by absolute sample number, so overwriting needs no repair: a block that has lost
// samples to the ring is never used whole, its surviving samples are read raw instead.
//
// Time windows are half-open, [t0, t1). Not thread-safe; Telemetry owns the buffers and is the
// only writer.
#pragma once

#include "model/telemetry/telemetrygaps.h"

#include <QList>
#include <QStringList>
#include <QtGlobal>
#include <initializer_list>
#include <optional>
#include <vector>

namespace tipscope::model {

enum class AppendResult {
    Accepted,
    OutOfOrder,      // older than the newest sample held
    WrongValueCount, // not exactly one value per series
    UnknownKey,      // Telemetry only: no buffer of that key was created
};

// Where decimate() puts the edges between columns.
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

// One non-empty time column of a decimated window.
struct MinMaxBucket {
    qint64 startMs = 0;   // start of the column, whether or not a sample falls on it
    qint64 minTimeMs = 0; // time of the earliest sample holding the minimum
    qint32 min = 0;
    qint64 maxTimeMs = 0; // time of the earliest sample holding the maximum
    qint32 max = 0;
    int count = 0; // samples in the column
};

class TelemetryBuffer {
public:
    // 24 hours at 10 Hz.
    static constexpr int kDefaultCapacity = 864000;
    // Samples per block of the finest summary level.
    static constexpr int kFinestBlock = 64;
    // ColumnEdges::Blocks moves edges only when a column holds this many finest blocks.
    static constexpr int kSnapMinBlocks = 4;

    struct Sample {
        qint64 timeMs = 0;
        qint32 value = 0;
    };

    // Over an empty window count is 0 and the other fields are 0.
    struct Stats {
        qint32 min = 0;
        qint32 max = 0;
        double mean = 0;
        qint64 count = 0;
    };

    explicit TelemetryBuffer(const QStringList &series, int capacity = kDefaultCapacity);

    [[nodiscard]] const QStringList &seriesNames() const { return m_names; }
    [[nodiscard]] int seriesCount() const { return int(m_names.size()); }
    // -1 when there is no series of that name.
    [[nodiscard]] int seriesIndex(const QString &name) const { return int(m_names.indexOf(name)); }

    [[nodiscard]] int capacity() const { return m_capacity; }
    [[nodiscard]] int size() const { return int(qMin<qint64>(m_total, m_capacity)); }
    [[nodiscard]] bool isEmpty() const { return m_total == 0; }
    // Both 0 when empty.
    [[nodiscard]] qint64 firstTime() const;
    [[nodiscard]] qint64 lastTime() const { return m_lastTime; }
    [[nodiscard]] qint64 totalAppended() const { return m_total; }
    [[nodiscard]] qint64 outOfOrderCount() const { return m_outOfOrder; }
    // Samples refused for not having exactly one value per series.
    [[nodiscard]] qint64 malformedCount() const { return m_malformed; }

    // `values` holds one value per series, in the order of seriesNames().
    AppendResult append(qint64 timeMs, const qint32 *values, qsizetype count);
    AppendResult append(qint64 timeMs, std::initializer_list<qint32> values) {
        return append(timeMs, values.begin(), qsizetype(values.size()));
    }
    AppendResult append(qint64 timeMs, const QList<qint32> &values) {
        return append(timeMs, values.constData(), values.size());
    }

    // Continuity broke at `timeMs` (the line went down, the device stopped answering): the next
    // sample is not joined to the one before it, and nothing is read in between.
    void markGap(qint64 timeMs, TelemetryGap::Cause cause) {
        m_gaps.open(timeMs, m_lastTime, cause);
    }
    [[nodiscard]] const TelemetryGaps &gaps() const { return m_gaps; }

    // The newest sample at or before `timeMs` (a crosshair readout); nullopt if there is none or
    // `timeMs` falls in a gap.
    [[nodiscard]] std::optional<Sample> valueAt(int series, qint64 timeMs) const;
    // Every sample of [t0, t1), oldest first (CSV export).
    [[nodiscard]] QList<Sample> samples(int series, qint64 t0, qint64 t1) const;
    // [t0, t1) split into `buckets` equal time columns; empty columns are left out, so gaps in
    // the data stay visible as gaps.
    [[nodiscard]] QList<MinMaxBucket> decimate(int series, qint64 t0, qint64 t1, int buckets) const;
    // decimate() of several series over the same columns, one list per entry of `series` (empty
    // for an unknown series). A chart asks for all the series of a port at once: the search for
    // the columns' edges does not depend on the series and is done once.
    [[nodiscard]] QList<QList<MinMaxBucket>> decimate(const QList<int> &series, qint64 t0,
                                                      qint64 t1, int buckets,
                                                      ColumnEdges edges = ColumnEdges::Exact) const;
    [[nodiscard]] Stats windowStats(int series, qint64 t0, qint64 t1) const;

    // Heap bytes allocated for samples and summaries plus the object itself (series names aside).
    [[nodiscard]] qint64 memoryBytes() const;
    // memoryBytes() over the allocated sample slots times the series count.
    [[nodiscard]] double bytesPerSamplePerSeries() const;

private:
    struct Extremes;

    // One series' values by ring position: int16 until a value does not fit, then int32.
    class Column {
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
    [[nodiscard]] qint64 oldestIndex() const { return m_total - size(); }
    [[nodiscard]] bool isSeries(int series) const { return series >= 0 && series < seriesCount(); }

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
    // The sample numbers [first, last) of each non-empty column of decimate(), with the column.
    struct ColumnRange {
        int column = 0;
        qint64 first = 0;
        qint64 last = 0;
    };
    [[nodiscard]] std::vector<ColumnRange> columnRanges(qint64 t0, qint64 t1, int buckets,
                                                        ColumnEdges edges) const;
    [[nodiscard]] static qint64 columnStart(qint64 t0, qint64 t1, int buckets, int column);

    QStringList m_names;
    int m_capacity;
    qint64 m_total = 0;    // samples ever accepted; sample n sits at ring position n % capacity
    qint64 m_lapStart = 0; // the sample number at ring position 0 in the current lap
    qint64 m_lastTime = 0;
    qint64 m_outOfOrder = 0;
    qint64 m_malformed = 0;
    std::vector<qint64> m_times;
    std::vector<Column> m_columns;
    std::vector<Level> m_levels;
    TelemetryGaps m_gaps;
};

} // namespace tipscope::model
