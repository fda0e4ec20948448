// TelemetryBuffer: the sample history of one port (or one feeder).
//
// The series (for example "tip", "setpoint", "power", "status") are fixed at construction; each
// sample is one timestamp (ms since the epoch) with one integer per series, in wire units. Samples
// must arrive in non-decreasing time: an older one is refused and counted, never inserted, so
// every query can binary-search on time.
//
// Two kinds, chosen at construction. A single-tier buffer (a capacity) is one TelemetryRing of
// every sample: when `capacity()` samples are held, each new sample overwrites the oldest. A
// tiered buffer (TelemetryTiers, what a live Telemetry makes) keeps every sample of the newest
// hours (the full-rate tier, from fullRateFrom() on) and folds older ones into one summary per
// time bucket (the older tier: first sample, min, max, sum and count of each series), so a day
// of a port fits in a few MB; the oldest summaries go when the older tier's budget is full.
// Buckets are aligned to multiples of bucketMs since the epoch, and a bucket never spans a gap:
// it ends where a gap starts, so a gap stays a gap in the older tier too.
//
// What the queries give in the older tier:
// - decimate(): min and max per column as before, each column taking the whole buckets that
//   start in it. A column starting and ending on bucket edges is exact (what the samples would
//   give); otherwise a bucket straddling an edge counts in the column of its start. Extremes are
//   dated at their bucket's first sample, up to a bucket early. No seam at the
//   boundary: a column reaching across it merges both tiers.
// - windowStats(): min, max, mean and count over whole buckets starting in the window.
// - valueAt(): the newest summary at or before the time, by its first sample (a real sample, at
//   its own time).
// - samples(): full-rate samples only, nothing before fullRateFrom(): exact samples (an export,
//   a measurement) exist only there. Callers that need them check fullRateFrom().
//
// Time windows are half-open, [t0, t1). Not thread-safe; Telemetry owns the buffers and is the
// only writer.
#pragma once

#include "model/telemetry/telemetrygaps.h"
#include "model/telemetry/telemetryring.h"
#include "model/telemetry/telemetrytiers.h"

#include <QList>
#include <QStringList>
#include <QtGlobal>
#include <initializer_list>
#include <optional>

namespace tipscope::model {

enum class AppendResult {
    Accepted,
    OutOfOrder,      // older than the newest sample held
    WrongValueCount, // not exactly one value per series
    UnknownKey,      // Telemetry only: no buffer of that key was created
};

// One non-empty time column of a decimated window.
struct MinMaxBucket {
    qint64 startMs = 0;   // start of the column, whether or not a sample falls on it
    qint64 minTimeMs = 0; // time of the earliest sample (older tier: bucket) holding the minimum
    qint32 min = 0;
    qint64 maxTimeMs = 0; // time of the earliest sample (older tier: bucket) holding the maximum
    qint32 max = 0;
    int count = 0; // samples in the column
};

class TelemetryBuffer {
public:
    // 24 hours at 10 Hz.
    static constexpr int kDefaultCapacity = TelemetryTiers::kDefaultMaxFullRateSamples;
    static constexpr int kFinestBlock = TelemetryRing::kFinestBlock;
    static constexpr int kSnapMinBlocks = TelemetryRing::kSnapMinBlocks;

    using Sample = TelemetrySample;

    // Over an empty window count is 0 and the other fields are 0.
    struct Stats {
        qint32 min = 0;
        qint32 max = 0;
        double mean = 0;
        qint64 count = 0;
    };

    // A single tier of `capacity` samples.
    explicit TelemetryBuffer(const QStringList &series, int capacity = kDefaultCapacity);
    // Tiered as `tiers` says (a single tier if !tiers.isTiered()).
    TelemetryBuffer(const QStringList &series, const TelemetryTiers &tiers);

    [[nodiscard]] const QStringList &seriesNames() const { return m_names; }
    [[nodiscard]] int seriesCount() const { return int(m_names.size()); }
    // -1 when there is no series of that name.
    [[nodiscard]] int seriesIndex(const QString &name) const { return int(m_names.indexOf(name)); }

    [[nodiscard]] const TelemetryTiers &tiers() const { return m_tiers; }
    [[nodiscard]] bool isTiered() const { return m_tiers.isTiered(); }
    // Samples the full-rate tier can hold now (a tiered one grows up to maxFullRateSamples).
    [[nodiscard]] int capacity() const { return m_recent.capacity(); }
    // Full-rate samples held.
    [[nodiscard]] int size() const { return m_recent.size(); }
    // Summaries held by the older tier (0 for a single tier).
    [[nodiscard]] int summaryCount() const { return m_old.size(); }
    [[nodiscard]] bool isEmpty() const { return m_total == 0; }
    // The oldest time held in either tier; both 0 when empty.
    [[nodiscard]] qint64 firstTime() const;
    // Where the full-rate tier starts: every sample from here on is held as it came.
    [[nodiscard]] qint64 fullRateFrom() const { return m_recent.firstTime(); }
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
    // `timeMs` falls in a gap. In the older tier: the newest summary's first sample.
    [[nodiscard]] std::optional<Sample> valueAt(int series, qint64 timeMs) const;
    // Every full-rate sample of [t0, t1), oldest first (CSV export); none before fullRateFrom().
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
    // memoryBytes() over the allocated full-rate sample slots times the series count.
    [[nodiscard]] double bytesPerSamplePerSeries() const;

private:
    [[nodiscard]] bool isSeries(int series) const { return series >= 0 && series < seriesCount(); }
    // The older tier's columns of series s: its first sample, min, max and sum, then the count.
    [[nodiscard]] int minColumn(int s) const { return seriesCount() + s; }
    [[nodiscard]] int maxColumn(int s) const { return 2 * seriesCount() + s; }
    [[nodiscard]] int sumColumn(int s) const { return 3 * seriesCount() + s; }
    [[nodiscard]] int countColumn() const { return 4 * seriesCount(); }

    // The full-rate ring is full before a sample at `timeMs`: grow it while it holds less than
    // the boundary, else fold its oldest bucket.
    void makeRoom(qint64 timeMs);
    void growFullRate(qint64 timeMs);
    void foldOldestBucket();

    QStringList m_names;
    TelemetryTiers m_tiers;
    TelemetryRing m_recent;
    TelemetryRing m_old; // capacity 1 and never used for a single tier
    qint64 m_total = 0;  // samples ever accepted
    qint64 m_lastTime = 0;
    qint64 m_outOfOrder = 0;
    qint64 m_malformed = 0;
    TelemetryGaps m_gaps;
};

} // namespace tipscope::model
