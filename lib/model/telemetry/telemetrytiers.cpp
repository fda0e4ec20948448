#include "model/telemetry/telemetrytiers.h"

#include <cmath>

namespace tipscope::model {

int TelemetryTiers::summaryCapacity() const {
    if (!isTiered() || bucketMs <= 0)
        return 1;
    const double buckets = double(qMax<qint64>(0, historyMs - fullRateMs)) / double(bucketMs);
    return int(qBound(1.0, std::ceil(buckets * kSummarySlack), 1e8));
}

double TelemetryTiers::summaryBytes(int seriesCount) {
    // Per summary: its time, a 16-bit count, per series first, min and max in 16 bits and a sum
    // that needs 32; each of the 4n + 1 columns carries 24-byte block summaries per 64 entries
    // (and per 4096, a 64th of that again).
    const int columns = 4 * seriesCount + 1;
    const double blockShare = 24.0 / 64.0 * (1.0 + 1.0 / 64.0);
    return 8.0 + 2.0 + seriesCount * (3 * 2.0 + 4.0) + columns * blockShare;
}

qint64 TelemetryTiers::summaryBudgetBytes(int seriesCount) const {
    return isTiered() ? qint64(std::ceil(summaryCapacity() * summaryBytes(seriesCount))) : 0;
}

TelemetryTiers TelemetryTiers::singleTier(int capacity) {
    TelemetryTiers t;
    t.fullRateMs = 0;
    t.historyMs = 0;
    t.maxFullRateSamples = qMax(1, capacity);
    return t;
}

} // namespace tipscope::model
