#include "linkstats.h"

#include <QCoreApplication>
#include <algorithm>
#include <vector>

namespace tipscope::link {

namespace {
struct LinkStatsTr {
    Q_DECLARE_TR_FUNCTIONS(LinkStats)
};
constexpr qint64 kRateWindowMs = 5000;
} // namespace

void LinkStats::recordAnswer(qint64 latencyUs, qint64 nowMs) {
    ++answered;
    if (recentLatencyUs.empty() && answered == 1) {
        minLatencyUs = maxLatencyUs = latencyUs;
    } else {
        minLatencyUs = std::min(minLatencyUs, latencyUs);
        maxLatencyUs = std::max(maxLatencyUs, latencyUs);
    }
    recentLatencyUs.push_back(latencyUs);
    if (recentLatencyUs.size() > kLatencyWindow)
        recentLatencyUs.pop_front();
    recentAnswerMs.push_back(nowMs);
    while (!recentAnswerMs.empty() && recentAnswerMs.front() < nowMs - kRateWindowMs)
        recentAnswerMs.pop_front();
}

qint64 LinkStats::percentileLatencyUs(double p) const {
    if (recentLatencyUs.empty())
        return 0;
    std::vector<qint64> v(recentLatencyUs.begin(), recentLatencyUs.end());
    const size_t k = std::min(v.size() - 1, size_t(p * double(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + qsizetype(k), v.end());
    return v[k];
}

qint64 LinkStats::medianLatencyUs() const {
    return percentileLatencyUs(0.5);
}

double LinkStats::transactionsPerSecond(qint64 nowMs) const {
    const auto first = std::find_if(recentAnswerMs.begin(), recentAnswerMs.end(),
                                    [nowMs](qint64 t) { return t >= nowMs - kRateWindowMs; });
    const auto n = std::distance(first, recentAnswerMs.end());
    return double(n) * 1000.0 / double(kRateWindowMs);
}

qint64 LinkStats::nakTotal() const {
    qint64 n = 0;
    for (qint64 v : naks)
        n += v;
    return n;
}

QString LinkStats::summary(qint64 nowMs) const {
    return LinkStatsTr::tr(
               "%1 tx/s, latency %2 ms median (%3-%4), %5 sent, %6 answered, %7 timeouts, "
               "%8 corrupted, %9 NAKs, %10 stray, %11 retries")
        .arg(transactionsPerSecond(nowMs), 0, 'f', 1)
        .arg(medianLatencyUs() / 1000.0, 0, 'f', 1)
        .arg(minLatencyUs / 1000.0, 0, 'f', 1)
        .arg(maxLatencyUs / 1000.0, 0, 'f', 1)
        .arg(sent)
        .arg(answered)
        .arg(timeouts)
        .arg(corrupted)
        .arg(nakTotal())
        .arg(stray)
        .arg(retries);
}

} // namespace tipscope::link
