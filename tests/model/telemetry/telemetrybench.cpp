#include "model/telemetry/telemetrybench.h"

#include "model/telemetry/telemetrybuffer.h"

#include <QElapsedTimer>
#include <QTextStream>
#include <algorithm>
#include <memory>
#include <random>

namespace tipscope::bench {

namespace {

using model::TelemetryBuffer;

constexpr int kPorts = 4;
constexpr int kSeries = 4;
constexpr int kSamples = TelemetryBuffer::kDefaultCapacity;
constexpr int kBuckets = 1920;
constexpr int kRuns = 9;
constexpr qint64 kStartMs = 1'700'000'000'000;
constexpr qint64 kStepMs = 100;

using Buffers = std::vector<std::unique_ptr<TelemetryBuffer>>;

// A tip that heats, idles with noise and now and then dips under load, so that the values and
// their extremes look like a working day rather than a constant.
std::vector<qint32> makeDay() {
    std::mt19937 random(1);
    std::uniform_int_distribution<int> noise(-2, 2);
    std::uniform_int_distribution<int> roll(0, 999);
    std::vector<qint32> values(size_t(kSamples) * kSeries);
    qint32 tip = 25;
    for (size_t i = 0; i < size_t(kSamples); ++i) {
        tip = std::min(350, tip + 5) + noise(random);
        if (roll(random) == 0)
            tip -= 40; // soldering a big pad
        const qint32 power = std::clamp((350 - tip) * 40, 0, 1000);
        qint32 *row = &values[i * kSeries];
        row[0] = tip;
        row[1] = 350;
        row[2] = power;
        row[3] = tip < 340 ? 1 : 0;
    }
    return values;
}

// Returns the mean nanoseconds per append.
double fill(Buffers &buffers, const std::vector<qint32> &day) {
    const QStringList series = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                QStringLiteral("power"), QStringLiteral("status")};
    for (int port = 0; port < kPorts; ++port)
        buffers.push_back(std::make_unique<TelemetryBuffer>(series, kSamples));
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; i < kSamples; ++i) {
        const qint64 time = kStartMs + i * kStepMs;
        for (auto &buffer : buffers)
            buffer->append(time, &day[size_t(i) * kSeries], kSeries);
    }
    return double(timer.nsecsElapsed()) / (double(kSamples) * kPorts);
}

// Median over kRuns of the time for one decimate() per series and port, in milliseconds.
double medianDecimateMs(const Buffers &buffers, qint64 t0, qint64 t1) {
    std::vector<double> runs;
    for (int run = 0; run < kRuns; ++run) {
        QElapsedTimer timer;
        timer.start();
        for (const auto &buffer : buffers) {
            // An out-of-line call that allocates: the optimiser cannot drop it.
            for (int series = 0; series < kSeries; ++series)
                (void)buffer->decimate(series, t0, t1, kBuckets);
        }
        runs.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    std::sort(runs.begin(), runs.end());
    return runs[runs.size() / 2];
}

} // namespace

void runTelemetryBench(QTextStream &out) {
    Buffers buffers;
    const double appendNs = fill(buffers, makeDay());
    double bytes = 0;
    for (const auto &buffer : buffers)
        bytes = std::max(bytes, buffer->bytesPerSamplePerSeries());

    const qint64 first = buffers.front()->firstTime();
    const qint64 last = buffers.front()->lastTime();
    const double fullMs = medianDecimateMs(buffers, first, last + 1);
    const qint64 middle = first + (last - first) / 2;
    const double minuteMs = medianDecimateMs(buffers, middle, middle + 60'000);

    out << "telemetry.bytes_per_sample: " << QString::number(bytes, 'f', 2) << " bytes\n"
        << "telemetry.decimate_full_1920_ms: " << QString::number(fullMs, 'f', 3) << " ms\n"
        << "telemetry.decimate_1min_1920_ms: " << QString::number(minuteMs, 'f', 3) << " ms\n"
        << "telemetry.append_ns: " << QString::number(appendNs, 'f', 1) << " ns\n";
    out.flush();
}

} // namespace tipscope::bench
