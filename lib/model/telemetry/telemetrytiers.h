// TelemetryTiers: how much history a live TelemetryBuffer keeps, and how finely.
//
// A day of every sample of 32 stations does not fit in memory (about 2 GB at the demo's poll
// rates), and nobody needs every sample of this morning: a day's chart shows min and max per
// pixel column of 45 s anyway. So a tiered buffer keeps the samples of the newest `fullRateMs`
// (the boundary) in full and folds older ones into one summary per `bucketMs` of time (first
// sample, min, max, sum and count of every series); a day's chart looks the same. The summaries
// of `historyMs` minus the boundary fit the older tier; when it is full the oldest summary goes.
// Its size in bytes is fixed when the buffer is made: summaryBudgetBytes() (the byte budget),
// about 1.4 MB for a port's six series with the defaults.
//
// The boundary is a minimum: the full-rate tier grows (by copying into a larger ring) until it
// holds `fullRateMs`, then folds its oldest bucket whenever it needs room, so it holds between
// the boundary and about a quarter more. A port sampled faster than `maxFullRateSamples` over
// the boundary folds earlier. fullRateMs == 0 means one tier, the whole history at full rate in
// a ring of `maxFullRateSamples` (what TelemetryBuffer did before the tiers).
#pragma once

#include <QtGlobal>

namespace tipscope::model {

struct TelemetryTiers {
    static constexpr qint64 kMinuteMs = 60 * 1000;
    static constexpr qint64 kHourMs = 60 * kMinuteMs;
    static constexpr qint64 kDefaultFullRateMs = 2 * kHourMs;
    static constexpr qint64 kDefaultHistoryMs = 24 * kHourMs;
    // Finer than a day's pixel column (45 s at 1920 px) by far, coarse enough that a port's
    // summaries of 22 hours take about 1.4 MB.
    static constexpr qint64 kDefaultBucketMs = 5000;
    // 24 hours at 10 Hz: the single-tier ring of before.
    static constexpr int kDefaultMaxFullRateSamples = 864000;
    // Buckets cut short by a gap or an overflowing sum need entries beyond the plain count.
    static constexpr double kSummarySlack = 1.125;

    qint64 fullRateMs = kDefaultFullRateMs; // 0: a single tier
    qint64 historyMs = kDefaultHistoryMs;
    qint64 bucketMs = kDefaultBucketMs;
    int maxFullRateSamples = kDefaultMaxFullRateSamples;

    [[nodiscard]] bool isTiered() const { return fullRateMs > 0; }
    // Summaries the older tier holds: (history - boundary) / bucket, with slack; at least one.
    [[nodiscard]] int summaryCapacity() const;
    // Heap bytes of one summary of `seriesCount` series, its share of the ring's own block
    // summaries included (time, count, and first, min, max in 16 bits and the sum in 32).
    [[nodiscard]] static double summaryBytes(int seriesCount);
    // The older tier's byte budget: summaryCapacity() summaries.
    [[nodiscard]] qint64 summaryBudgetBytes(int seriesCount) const;
    // A single tier holding `capacity` samples.
    [[nodiscard]] static TelemetryTiers singleTier(int capacity);

    bool operator==(const TelemetryTiers &o) const {
        return fullRateMs == o.fullRateMs && historyMs == o.historyMs && bucketMs == o.bucketMs &&
               maxFullRateSamples == o.maxFullRateSamples;
    }
    bool operator!=(const TelemetryTiers &o) const { return !(*this == o); }
};

} // namespace tipscope::model
