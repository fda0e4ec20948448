#include "fleetday.h"

#include "benchsupport.h"

#include "model/telemetry/telemetry.h"

#include <QElapsedTimer>
#include <algorithm>

namespace tipscope::bench {

namespace {

using model::Telemetry;
using model::TelemetryBuffer;

constexpr int kColumns = 1920;
constexpr int kRuns = 9;
constexpr qint64 kStartMs = 1'700'000'000'000;
constexpr qint64 kHourMs = 3'600'000;
constexpr double kMB = 1024.0 * 1024.0;

// The series TelemetryRecorder records.
const QStringList kPortSeries = {QStringLiteral("tip"),        QStringLiteral("setpoint"),
                                 QStringLiteral("power"),      QStringLiteral("status"),
                                 QStringLiteral("transistor"), QStringLiteral("transformer")};
const QStringList kFeederSeries = {QStringLiteral("fed"), QStringLiteral("speed"),
                                   QStringLiteral("feeding")};

// A day of one channel at `hz` on a simulated clock: a tip at its setpoint with noise and a
// joint now and then, the hardware temperatures read every 2 s; a feeder feeding in bursts.
void fillChannel(Telemetry &telemetry, const QString &key, bool feeder, double hz, qint64 hours,
                 quint32 seed) {
    const qint64 count = qint64(double(hours * 3600) * hz);
    const double periodMs = 1000.0 / hz;
    quint32 random = seed;
    qint32 tip = 350;
    qint32 transistor = 30;
    qint32 fed = 0;
    QList<qint32> values(feeder ? kFeederSeries.size() : kPortSeries.size());
    for (qint64 i = 0; i < count; ++i) {
        random = random * 1664525u + 1013904223u;
        const qint64 time = kStartMs + qint64(double(i) * periodMs);
        if (feeder) {
            const bool feeding = (time / 20000) % 3 == 0;
            fed = feeding ? (fed + 1) % 200 : fed;
            values = {fed, 50, feeding ? 1 : 0};
        } else {
            tip = std::min(350, tip + 5) + int((random >> 28) % 5) - 2;
            if ((random >> 8) % 1000 == 0)
                tip -= 40;
            const qint32 power = std::clamp((350 - tip) * 40, 0, 1000);
            if (i % qMax<qint64>(1, qint64(2 * hz)) == 0)
                transistor = 30 + power * 3 / 100;
            values = {tip, 350, power, tip < 340 ? 1 : 0, transistor, 35 + power / 100};
        }
        telemetry.append(key, time, values);
    }
}

QString keyOf(int station, int channel) {
    return QStringLiteral("%1|%2")
        .arg(station, 2, 10, QLatin1Char('0'))
        .arg(fleetChannelName(channel));
}

struct Fleet {
    qint64 bytes = 0;
    double fullRateHours = 1e9;
    double hoursHeld = 1e9;
};

// `stations` stations into `telemetry`, single-tier (`capacity` samples) or tiered (0).
Fleet fill(Telemetry &telemetry, const ChannelRates &rates, int stations, qint64 hours,
           int capacity) {
    Fleet fleet;
    for (int s = 0; s < stations; ++s) {
        for (int c = 0; c <= kFleetPorts; ++c) {
            const bool feeder = c == kFleetPorts;
            const QString key = keyOf(s, c);
            const QStringList &series = feeder ? kFeederSeries : kPortSeries;
            if (capacity > 0)
                telemetry.ensureBuffer(key, series, capacity);
            else
                telemetry.ensureBuffer(key, series);
            fillChannel(telemetry, key, feeder, rates[size_t(c)], hours, quint32(s * 7 + c + 1));
            const TelemetryBuffer &b = *telemetry.buffer(key);
            fleet.bytes += b.memoryBytes();
            if (feeder)
                continue;
            const auto hoursOf = [](qint64 ms) { return double(ms) / double(kHourMs); };
            fleet.fullRateHours =
                qMin(fleet.fullRateHours, hoursOf(b.lastTime() - b.fullRateFrom()));
            fleet.hoursHeld = qMin(fleet.hoursHeld, hoursOf(b.lastTime() - b.firstTime()));
        }
    }
    return fleet;
}

// The day's chart of station 0's ports: every series, 1920 columns; median milliseconds.
double decimateDayMs(const Telemetry &telemetry, qint64 hours) {
    QList<double> runs;
    const QList<int> series = {0, 1, 2, 3, 4, 5};
    qint64 columns = 0;
    for (int r = 0; r < kRuns; ++r) {
        QElapsedTimer timer;
        timer.start();
        for (int c = 0; c < kFleetPorts; ++c) {
            const auto result = telemetry.buffer(keyOf(0, c))
                                    ->decimate(series, kStartMs, kStartMs + hours * kHourMs,
                                               kColumns, model::ColumnEdges::Blocks);
            columns += result.constFirst().size();
        }
        runs.append(double(timer.nsecsElapsed()) / 1e6);
    }
    if (columns == 0)
        printError(QStringLiteral("the day's decimation gave no columns"));
    return quantile(runs, 0.5);
}

} // namespace

QString fleetChannelName(int index) {
    return index < kFleetPorts ? QStringLiteral("port%1").arg(index + 1) : QStringLiteral("feeder");
}

std::array<qint64, kFleetPorts + 1> channelSamples(const Telemetry &telemetry) {
    std::array<qint64, kFleetPorts + 1> n{};
    for (const model::TelemetryKey &key : telemetry.keys())
        for (int c = 0; c <= kFleetPorts; ++c)
            if (key.endsWith(QLatin1Char('|') + fleetChannelName(c)))
                n[size_t(c)] += telemetry.buffer(key)->totalAppended();
    return n;
}

void printDayMemory(const ChannelRates &rates, int stations, qint64 hours) {
    const model::TelemetryTiers tiers;
    printFigure(QStringLiteral("fleet.summary_budget_mb_port"),
                double(tiers.summaryBudgetBytes(int(kPortSeries.size()))) / kMB,
                QStringLiteral("MB"), 2);
    printFigure(QStringLiteral("fleet.summary_budget_mb_feeder"),
                double(tiers.summaryBudgetBytes(int(kFeederSeries.size()))) / kMB,
                QStringLiteral("MB"), 2);
    {
        const qint64 rssBefore = selfStatusBytes("VmRSS:");
        Telemetry telemetry;
        const Fleet tiered = fill(telemetry, rates, stations, hours, 0);
        const qint64 rssAfter = selfStatusBytes("VmRSS:");
        printFigure(QStringLiteral("fleet.memory_mb_24h"), double(tiered.bytes) / kMB,
                    QStringLiteral("MB"));
        printFigure(QStringLiteral("fleet.rss_mb_24h"), double(rssAfter - rssBefore) / kMB,
                    QStringLiteral("MB"));
        printFigure(QStringLiteral("fleet.full_rate_hours"), tiered.fullRateHours,
                    QStringLiteral("h"), 2);
        printFigure(QStringLiteral("fleet.hours_held"), tiered.hoursHeld, QStringLiteral("h"), 2);
        printFigure(QStringLiteral("fleet.decimate_day_ms"), decimateDayMs(telemetry, hours),
                    QStringLiteral("ms"), 2);
    }
    Telemetry single;
    const Fleet one = fill(single, rates, 1, hours, TelemetryBuffer::kDefaultCapacity);
    printFigure(QStringLiteral("fleet.memory_mb_24h_single_tier"),
                double(one.bytes) * stations / kMB, QStringLiteral("MB"));
    printFigure(QStringLiteral("fleet.single_tier_hours_held"), one.hoursHeld, QStringLiteral("h"),
                2);
    printFigure(QStringLiteral("fleet.decimate_day_ms_single_tier"), decimateDayMs(single, hours),
                QStringLiteral("ms"), 2);
}

} // namespace tipscope::bench
