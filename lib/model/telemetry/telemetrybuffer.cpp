// Storage side of TelemetryBuffer: validation, the full-rate tier's growth and the fold of its
// oldest bucket into the older tier. The queries are in telemetrybufferquery.cpp.
#include "model/telemetry/telemetrybuffer.h"

#include <cmath>
#include <limits>
#include <vector>

namespace tipscope::model {

namespace {

// A tiered buffer's full-rate ring starts this small and grows, sized from the rate it sees,
// only while it holds less than the boundary: a short boundary costs no more than it needs.
constexpr int kFirstFullRateCapacity = 1024;
// A ring that must grow takes at least a quarter more, so copying stays amortised.
constexpr double kMinGrowth = 1.25;
// Grown to the boundary's share of samples at the rate seen so far, with this much to spare.
constexpr double kGrowthSlack = 1.2;

qint64 floorDiv(qint64 a, qint64 b) {
    return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0);
}

bool fitsInt32(qint64 v) {
    return v >= std::numeric_limits<qint32>::min() && v <= std::numeric_limits<qint32>::max();
}

} // namespace

TelemetryBuffer::TelemetryBuffer(const QStringList &series, int capacity)
    : TelemetryBuffer(series, TelemetryTiers::singleTier(capacity)) {}

TelemetryBuffer::TelemetryBuffer(const QStringList &series, const TelemetryTiers &tiers)
    : m_names(series)
    , m_tiers(tiers)
    , m_recent(int(series.size()), tiers.isTiered()
                                       ? qMin(kFirstFullRateCapacity, tiers.maxFullRateSamples)
                                       : tiers.maxFullRateSamples)
    , m_old(tiers.isTiered() ? 4 * int(series.size()) + 1 : 0,
            tiers.isTiered() ? tiers.summaryCapacity() : 1) {}

qint64 TelemetryBuffer::firstTime() const {
    if (isEmpty())
        return 0;
    return m_old.isEmpty() ? m_recent.firstTime() : m_old.firstTime();
}

AppendResult TelemetryBuffer::append(qint64 timeMs, const qint32 *values, qsizetype count) {
    if (count != seriesCount()) {
        ++m_malformed;
        return AppendResult::WrongValueCount;
    }
    // Every query binary-searches on time, so an older sample would corrupt them all.
    if (m_total > 0 && timeMs < m_lastTime) {
        ++m_outOfOrder;
        return AppendResult::OutOfOrder;
    }
    if (isTiered() && m_recent.size() == m_recent.capacity())
        makeRoom(timeMs);
    m_recent.append(timeMs, values);
    ++m_total;
    m_lastTime = timeMs;
    m_gaps.close(timeMs);
    m_gaps.trim(firstTime());
    return AppendResult::Accepted;
}

void TelemetryBuffer::makeRoom(qint64 timeMs) {
    const bool withinBoundary = m_recent.firstTime() > timeMs - m_tiers.fullRateMs;
    if (withinBoundary && m_recent.capacity() < m_tiers.maxFullRateSamples)
        growFullRate(timeMs);
    else
        foldOldestBucket();
}

// Sized from the rate seen so far, so a port polled at 8 Hz settles near two hours of samples
// instead of doubling past it; a faster port grows again later.
void TelemetryBuffer::growFullRate(qint64 timeMs) {
    const int held = m_recent.size();
    const double span = double(qMax<qint64>(1, timeMs - m_recent.firstTime()));
    const double wanted = double(held) * double(m_tiers.fullRateMs) / span * kGrowthSlack;
    const double atLeast = std::ceil(double(m_recent.capacity()) * kMinGrowth);
    const int capacity =
        int(qMin(double(m_tiers.maxFullRateSamples), qMax(atLeast, std::ceil(wanted))));
    TelemetryRing bigger(seriesCount(), capacity);
    std::vector<qint32> values(static_cast<size_t>(seriesCount()));
    for (int i = 0; i < held; ++i) {
        for (int s = 0; s < seriesCount(); ++s)
            values[size_t(s)] = m_recent.valueAt(s, i);
        bigger.append(m_recent.timeAt(i), values.data());
    }
    m_recent = std::move(bigger);
}

// The oldest full-rate sample and those after it in its bucket become one summary. The bucket
// ends early where a gap starts (samples on both sides of a gap are never summarised together,
// so the gap stays visible) or where a sum would no longer fit the summary's 32 bits.
void TelemetryBuffer::foldOldestBucket() {
    const int n = seriesCount();
    const qint64 first = m_recent.timeAt(0);
    const qint64 bucketMs = qMax<qint64>(1, m_tiers.bucketMs);
    qint64 end = (floorDiv(first, bucketMs) + 1) * bucketMs;
    const QList<TelemetryGap> gaps = m_gaps.within(first + 1, end);
    if (!gaps.isEmpty())
        end = qMin(end, qMax(first + 1, gaps.constFirst().startMs));
    const int candidates = qMax(1, m_recent.countBefore(end));

    std::vector<qint32> summary(size_t(4 * n + 1));
    std::vector<qint64> sums(static_cast<size_t>(n));
    for (int s = 0; s < n; ++s) {
        const qint32 v = m_recent.valueAt(s, 0);
        summary[size_t(s)] = v;
        summary[size_t(minColumn(s))] = v;
        summary[size_t(maxColumn(s))] = v;
        sums[size_t(s)] = v;
    }
    int count = 1;
    for (; count < candidates; ++count) {
        bool fits = true;
        for (int s = 0; s < n && fits; ++s)
            fits = fitsInt32(sums[size_t(s)] + m_recent.valueAt(s, count));
        if (!fits)
            break;
        for (int s = 0; s < n; ++s) {
            const qint32 v = m_recent.valueAt(s, count);
            summary[size_t(minColumn(s))] = qMin(summary[size_t(minColumn(s))], v);
            summary[size_t(maxColumn(s))] = qMax(summary[size_t(maxColumn(s))], v);
            sums[size_t(s)] += v;
        }
    }
    for (int s = 0; s < n; ++s)
        summary[size_t(sumColumn(s))] = qint32(sums[size_t(s)]);
    summary[size_t(countColumn())] = count;
    m_old.append(first, summary.data());
    m_recent.dropOldest(count);
}

qint64 TelemetryBuffer::memoryBytes() const {
    // The rings count their own objects, which sit inside this one.
    return qint64(sizeof(*this)) - qint64(2 * sizeof(TelemetryRing)) + m_recent.memoryBytes() +
           (isTiered() ? m_old.memoryBytes() : qint64(sizeof(TelemetryRing)));
}

double TelemetryBuffer::bytesPerSamplePerSeries() const {
    const qint64 slots = m_recent.allocatedSlots();
    if (slots == 0)
        return 0;
    return double(memoryBytes()) / double(slots * qMax(1, seriesCount()));
}

} // namespace tipscope::model
