// Brute-force twin of TelemetryBuffer for the tests: keeps the newest `capacity` samples in a
// plain vector and answers decimation and window statistics by reading every sample, with bucket
// edges computed independently (plain qint64 arithmetic, fine for the test's time ranges). Also
// a seeded generator of telemetry-like data: mostly 100 ms steps, repeated timestamps, gaps of
// a second to ten minutes (empty buckets), a random walk with spikes.
#pragma once

#include "model/telemetry/telemetrybuffer.h"

#include <algorithm>
#include <deque>
#include <random>

namespace tipscope::model::test {

struct ReferenceSample {
    qint64 timeMs = 0;
    QList<qint32> values;
};

class ReferenceBuffer {
public:
    explicit ReferenceBuffer(int capacity)
        : m_capacity(capacity) {}

    void append(qint64 timeMs, const QList<qint32> &values) {
        m_samples.push_back({timeMs, values});
        if (int(m_samples.size()) > m_capacity)
            m_samples.pop_front();
    }
    [[nodiscard]] const std::deque<ReferenceSample> &samples() const { return m_samples; }

    [[nodiscard]] QList<MinMaxBucket> decimate(int series, qint64 t0, qint64 t1,
                                               int buckets) const {
        QList<MinMaxBucket> result;
        const qint64 span = t1 - t0;
        for (int k = 0; k < buckets; ++k) {
            const qint64 start = t0 + span * k / buckets;
            const qint64 end = t0 + span * (k + 1) / buckets;
            MinMaxBucket bucket{start, 0, 0, 0, 0, 0};
            for (auto s = firstAtOrAfter(start); s != m_samples.end() && s->timeMs < end; ++s) {
                const qint32 v = s->values.at(series);
                if (bucket.count == 0 || v < bucket.min) {
                    bucket.min = v;
                    bucket.minTimeMs = s->timeMs;
                }
                if (bucket.count == 0 || v > bucket.max) {
                    bucket.max = v;
                    bucket.maxTimeMs = s->timeMs;
                }
                ++bucket.count;
            }
            if (bucket.count > 0)
                result.append(bucket);
        }
        return result;
    }

    [[nodiscard]] TelemetryBuffer::Stats windowStats(int series, qint64 t0, qint64 t1) const {
        TelemetryBuffer::Stats stats;
        qint64 sum = 0;
        for (const ReferenceSample &s : m_samples) {
            if (s.timeMs < t0 || s.timeMs >= t1)
                continue;
            const qint32 v = s.values.at(series);
            stats.min = stats.count == 0 ? v : std::min(stats.min, v);
            stats.max = stats.count == 0 ? v : std::max(stats.max, v);
            sum += v;
            ++stats.count;
        }
        stats.mean = stats.count == 0 ? 0.0 : double(sum) / double(stats.count);
        return stats;
    }

private:
    [[nodiscard]] std::deque<ReferenceSample>::const_iterator firstAtOrAfter(qint64 timeMs) const {
        return std::lower_bound(m_samples.begin(), m_samples.end(), timeMs,
                                [](const ReferenceSample &s, qint64 t) { return s.timeMs < t; });
    }

    int m_capacity;
    std::deque<ReferenceSample> m_samples;
};

// Seeded, so every run sees the same data.
class SampleGenerator {
public:
    SampleGenerator(quint32 seed, int seriesCount, bool wide)
        : m_random(seed)
        , m_values(seriesCount, 350)
        , m_wide(wide) {}

    [[nodiscard]] qint64 nextTime() {
        const int roll = pick(0, 999);
        if (roll < 50)
            return m_time; // the station answered twice within a millisecond
        if (roll == 50)
            m_time += pick(1000, 600 * 1000); // a pause in polling
        else
            m_time += 100;
        return m_time;
    }

    [[nodiscard]] QList<qint32> nextValues() {
        for (qint32 &v : m_values) {
            const int roll = pick(0, 999);
            if (roll < 5)
                v = m_wide ? pick(-2'000'000'000, 2'000'000'000) : pick(-32768, 32767);
            else
                v = std::clamp(v + pick(-3, 3), -32768, 32767);
        }
        return m_values;
    }

    [[nodiscard]] int pick(int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(m_random);
    }

private:
    std::mt19937 m_random;
    QList<qint32> m_values;
    bool m_wide;
    qint64 m_time = 1'700'000'000'000;
};

} // namespace tipscope::model::test
