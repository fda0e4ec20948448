// Query side of TelemetryBuffer: each query asks both tiers over the same window and merges.
// Every sample is in exactly one tier, and both tiers split a window on the same column grid,
// so a column reaching across the boundary merges its two halves and the chart shows no seam.
#include "model/telemetry/telemetrybuffer.h"

namespace tipscope::model {

std::optional<TelemetryBuffer::Sample> TelemetryBuffer::valueAt(int series, qint64 timeMs) const {
    if (!isSeries(series) || isEmpty() || m_gaps.at(timeMs))
        return std::nullopt;
    if (const auto recent = m_recent.latestAt(series, timeMs))
        return recent;
    // A summary's first columns are its first sample.
    return isTiered() ? m_old.latestAt(series, timeMs) : std::nullopt;
}

QList<TelemetryBuffer::Sample> TelemetryBuffer::samples(int series, qint64 t0, qint64 t1) const {
    if (!isSeries(series))
        return {};
    return m_recent.samples(series, t0, t1);
}

QList<MinMaxBucket> TelemetryBuffer::decimate(int series, qint64 t0, qint64 t1, int buckets) const {
    return decimate(QList<int>{series}, t0, t1, buckets).constFirst();
}

namespace {

// `later` (the full-rate tier's part of a column) into `into` (the older tier's): on a tie the
// earlier extreme, the older tier's, stays, as within a tier.
void merge(TelemetryRing::Extreme &into, const TelemetryRing::Extreme &later) {
    if (later.min < into.min) {
        into.min = later.min;
        into.minTimeMs = later.minTimeMs;
    }
    if (later.max > into.max) {
        into.max = later.max;
        into.maxTimeMs = later.maxTimeMs;
    }
}

} // namespace

QList<QList<MinMaxBucket>> TelemetryBuffer::decimate(const QList<int> &series, qint64 t0, qint64 t1,
                                                     int buckets, ColumnEdges edges) const {
    QList<QList<MinMaxBucket>> result(series.size());
    std::vector<TelemetryRing::Pick> recentPicks;
    std::vector<TelemetryRing::Pick> oldPicks;
    QList<qsizetype> wanted; // the entries of `series` that name a series, in pick order
    for (qsizetype i = 0; i < series.size(); ++i) {
        const int s = series.at(i);
        if (!isSeries(s))
            continue;
        wanted.append(i);
        recentPicks.push_back({s, s});
        oldPicks.push_back({minColumn(s), maxColumn(s)});
    }
    if (wanted.isEmpty())
        return result;
    const std::vector<TelemetryRing::Column> recent =
        m_recent.columns(recentPicks, TelemetryRing::kCountEntries, t0, t1, buckets, edges);
    std::vector<TelemetryRing::Column> old;
    if (isTiered() && !m_old.isEmpty() && t0 < fullRateFrom())
        old = m_old.columns(oldPicks, countColumn(), t0, t1, buckets, edges);
    for (qsizetype w : std::as_const(wanted))
        result[w].reserve(qsizetype(recent.size() + old.size()));

    // Both lists are in column order; the older tier's columns come first in time.
    size_t r = 0;
    size_t o = 0;
    while (r < recent.size() || o < old.size()) {
        const bool takeOld =
            o < old.size() && (r == recent.size() || old[o].column <= recent[r].column);
        const bool takeRecent =
            r < recent.size() && (o == old.size() || recent[r].column <= old[o].column);
        TelemetryRing::Column column = takeOld ? old[o] : recent[r];
        if (takeOld && takeRecent) {
            column.count += recent[r].count;
            for (size_t p = 0; p < column.extremes.size(); ++p)
                merge(column.extremes[p], recent[r].extremes[p]);
        }
        o += takeOld ? 1 : 0;
        r += takeRecent ? 1 : 0;
        const qint64 start = TelemetryRing::columnStart(t0, t1, buckets, column.column);
        for (qsizetype p = 0; p < wanted.size(); ++p) {
            const TelemetryRing::Extreme &e = column.extremes[size_t(p)];
            result[wanted.at(p)].append(
                MinMaxBucket{start, e.minTimeMs, e.min, e.maxTimeMs, e.max, int(column.count)});
        }
    }
    return result;
}

TelemetryBuffer::Stats TelemetryBuffer::windowStats(int series, qint64 t0, qint64 t1) const {
    if (!isSeries(series) || t1 <= t0)
        return {};
    TelemetryRing::Totals total =
        m_recent.totals({series, series}, series, TelemetryRing::kCountEntries, t0, t1);
    if (isTiered() && t0 < fullRateFrom()) {
        const TelemetryRing::Totals old = m_old.totals({minColumn(series), maxColumn(series)},
                                                       sumColumn(series), countColumn(), t0, t1);
        if (old.count > 0 && total.count > 0) {
            total.min = qMin(total.min, old.min);
            total.max = qMax(total.max, old.max);
            total.sum += old.sum;
            total.count += old.count;
        } else if (old.count > 0) {
            total = old;
        }
    }
    if (total.count == 0)
        return {};
    return Stats{total.min, total.max, double(total.sum) / double(total.count), total.count};
}

} // namespace tipscope::model
