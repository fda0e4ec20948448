// LinkStats: what the line has done, for the status bar, the support report and benchmarks.
// Plain data updated by RequestQueue; latencies are kept for the most recent answers only, so
// memory stays bounded however long the line runs.
#pragma once

#include <QMap>
#include <QString>
#include <deque>

namespace tipscope::link {

struct LinkStats {
    qint64 sent = 0;          // frames written, retries included
    qint64 sentBytes = 0;     // their bytes: with receivedBytes, how busy the wire was
    qint64 receivedBytes = 0; // every byte received, inside frames or not
    qint64 answered = 0;      // requests that ended with a valid A or N answer
    qint64 timeouts = 0;
    qint64 probesUnanswered = 0; // discovery probes to empty addresses: expected silence
    qint64 corrupted = 0;        // BCC or format errors in received data
    qint64 stray = 0;            // valid frames that matched no outstanding request
    qint64 lateAnswers = 0;      // of those, answers that came after their request timed out
    qint64 retries = 0;
    qint64 skipped = 0; // requests withdrawn before they were sent
    qint64 coalesced = 0;
    qint64 discardedBytes = 0;
    QMap<int, qint64> naks; // by NAK code

    static constexpr size_t kLatencyWindow = 1000;
    std::deque<qint64> recentLatencyUs;
    qint64 minLatencyUs = 0, maxLatencyUs = 0;
    std::deque<qint64> recentAnswerMs; // for the transaction rate

    void recordAnswer(qint64 latencyUs, qint64 nowMs);
    [[nodiscard]] qint64 medianLatencyUs() const;
    [[nodiscard]] qint64 percentileLatencyUs(double p) const;
    [[nodiscard]] double transactionsPerSecond(qint64 nowMs) const;
    [[nodiscard]] qint64 nakTotal() const;
    [[nodiscard]] QString summary(qint64 nowMs) const;
};

} // namespace tipscope::link
