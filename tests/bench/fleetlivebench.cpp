#include "fleetlivebench.h"

#include "allocationcount.h"
#include "benchsupport.h"
#include "eventtally.h"
#include "fleetday.h"
#include "processactivity.h"
#include "simstations.h"
#include "wirefloor.h"

#include "model/workspace/workspace.h"
#include "pages/fleet/fleetpage.h"

#include <QElapsedTimer>
#include <QTextStream>
#include <memory>
#include <numeric>
#include <optional>
#include <vector>

namespace tipscope::bench {

namespace {

constexpr int kConnectMs = 120000;
// Discovery, the first reading of every setting and the tips heating up stay out of the figures.
constexpr int kWarmupMs = 10000;
constexpr int kDayHours = 24;
constexpr int kFloorSeconds = 30;

// What a line's link statistics say at one moment.
struct LineCounts {
    qint64 answered = 0;
    qint64 bytes = 0; // sent and received
};

// Everything measured at the start and the end of the run.
struct Snapshot {
    std::vector<LineCounts> lines;
    std::array<qint64, kFleetPorts + 1> samples{};
    qint64 cpuUs = 0;
    qint64 simCpuUs = 0;
};

model::WorkspaceLine tcpLine(const QString &name, const QString &where) {
    model::WorkspaceLine l;
    l.name = name;
    l.session.line.kind = link::LineSettings::Kind::Tcp;
    l.session.line.tcpHost = where.section(QLatin1Char(':'), 0, 0);
    l.session.line.tcpPort = quint16(where.section(QLatin1Char(':'), 1).toUInt());
    return l;
}

// Starts the simulators and returns the workspace file of their lines; empty on failure.
model::WorkspaceFile startSimulators(std::vector<SimStation> &sims, int stations, int chunkMs) {
    const QStringList args = {QStringLiteral("--model"),  QStringLiteral("DME"),
                              QStringLiteral("--feeder"), QStringLiteral("--activity"),
                              QStringLiteral("--tcp"),    QStringLiteral("127.0.0.1:0"),
                              QStringLiteral("--pace"),   QString::number(kPaceBaud),
                              QStringLiteral("--chunk"),  QString::number(chunkMs)};
    sims = startSimStations(stations, [&](int) { return args; });
    model::WorkspaceFile file;
    for (const SimStation &station : sims)
        file.lines.append(tcpLine(station.sim->name(), station.address));
    return file;
}

bool allConnected(const model::Workspace &workspace) {
    for (int i = 0; i < workspace.count(); ++i) {
        const model::Session &s = *workspace.session(i);
        if (s.state() != model::Session::State::Connected || !s.station() || !s.feeder())
            return false;
    }
    return true;
}

Snapshot snapshot(const model::Workspace &workspace, const std::vector<SimStation> &sims) {
    Snapshot s;
    for (int i = 0; i < workspace.count(); ++i) {
        model::Session &session = *workspace.session(i);
        const link::LinkStats &stats = session.line()->queue().stats();
        s.lines.push_back({stats.answered, stats.sentBytes + stats.receivedBytes});
        const auto samples = channelSamples(session.telemetry());
        for (size_t c = 0; c < samples.size(); ++c)
            s.samples[c] += samples[c];
    }
    for (const SimStation &station : sims)
        s.simCpuUs += processCpuUs(station.sim->pid()).value_or(0);
    s.cpuUs = selfCpuUs();
    return s;
}

// The lines' rates against their wires' limits; returns the achieved transactions a second.
double printRates(const model::Workspace &workspace, const Snapshot &before, const Snapshot &after,
                  double seconds) {
    double rateSum = 0, limitSum = 0;
    QList<double> latencies, periods, wires; // latencies: every line's last answers, pooled
    for (int i = 0; i < workspace.count(); ++i) {
        const qint64 answered = after.lines[size_t(i)].answered - before.lines[size_t(i)].answered;
        const qint64 bytes = after.lines[size_t(i)].bytes - before.lines[size_t(i)].bytes;
        const double rate = double(answered) / seconds;
        const double limit = pacedWireLimitTxPerS(answered, bytes);
        const QString line = workspace.line(i).name;
        printFigure(QStringLiteral("fleet.%1_tx_per_s").arg(line), rate, QStringLiteral("tx/s"));
        printFigure(QStringLiteral("fleet.%1_wire_limit_tx_per_s").arg(line), limit,
                    QStringLiteral("tx/s"));
        rateSum += rate;
        limitSum += limit;
        if (rate > 0 && limit > 0) {
            periods.append(1000 / rate);
            wires.append(1000 / limit);
            for (const qint64 us : workspace.session(i)->line()->queue().stats().recentLatencyUs)
                latencies.append(double(us) / 1000);
        }
    }
    printFigure(QStringLiteral("fleet.tx_per_s"), rateSum, QStringLiteral("tx/s"));
    printFigure(QStringLiteral("fleet.wire_limit_tx_per_s"), limitSum, QStringLiteral("tx/s"));
    printFigure(QStringLiteral("fleet.rate_ratio"), limitSum > 0 ? rateSum / limitSum : 0,
                QString(), 3);
    // Where a transaction's time goes beyond its wire time: before the answer was complete (the
    // simulator's and this process's wake-ups, the loopback) or after it (choosing and sending
    // the next request).
    const double period = quantile(periods, 0.5), wire = quantile(wires, 0.5);
    const double latency =
        latencies.isEmpty()
            ? 0
            : std::accumulate(latencies.begin(), latencies.end(), 0.0) / double(latencies.size());
    printFigure(QStringLiteral("fleet.tx_period_ms"), period, QStringLiteral("ms"), 2);
    printFigure(QStringLiteral("fleet.tx_wire_ms"), wire, QStringLiteral("ms"), 2);
    printFigure(QStringLiteral("fleet.answer_latency_ms_mean"), latency, QStringLiteral("ms"), 2);
    printFigure(QStringLiteral("fleet.answer_latency_ms_p50"), quantile(latencies, 0.5),
                QStringLiteral("ms"), 2);
    printFigure(QStringLiteral("fleet.answer_latency_ms_p99"), quantile(latencies, 0.99),
                QStringLiteral("ms"), 2);
    printFigure(QStringLiteral("fleet.after_answer_ms"), period - latency, QStringLiteral("ms"), 2);
    return rateSum;
}

} // namespace

int runFleetLiveBench(const QStringList &args) {
    if (args.contains(QStringLiteral("--help")) || args.contains(QStringLiteral("-h"))) {
        QTextStream(stdout)
            << "Usage: tipscope-bench fleet [--stations N] [--minutes M] [--chunk-ms C] "
               "[--by-intervals] [--load L]\n"
               "N simulated lines (default 32; a DME and a feeder each, TCP, paced at 19200 "
               "baud)\n"
               "in one workspace with the fleet overview shown, measured for M minutes (default "
               "10,\n"
               "fractions allowed): CPU, transactions against the wire limit, tile latency, and "
               "the\n"
               "memory of a day of the fleet at the sample rates achieved. --by-intervals polls\n"
               "each line by its intervals only instead of filling its wire. --chunk-ms hands\n"
               "each answer over in chunks every C ms, as a USB adapter or a device server does\n"
               "(default 0: a byte at a time, the most wake-ups). First, for 30 s, the wire\n"
               "floor: a bare epoll client on the same simulators, the least CPU any client\n"
               "spends on these wires. --load runs L busy loops beside the whole run (floor\n"
               "included), for the figures on a machine with other work.\n";
        return 0;
    }
    const std::optional<qint64> stationsOption = wholeOption(args, "--stations", 32, 1, 256);
    const std::optional<double> minutesOption = numberOption(args, "--minutes", 10, 0.1, 24 * 60);
    const std::optional<qint64> chunkOption = wholeOption(args, "--chunk-ms", 0, 0, 1000);
    const std::optional<qint64> loadOption = wholeOption(args, "--load", 0, 0, 64);
    if (!stationsOption || !minutesOption || !chunkOption || !loadOption)
        return 2;
    const BusyLoad load{int(*loadOption)};
    printFigure(QStringLiteral("fleet.load_processes"), load.count(), QStringLiteral("loops"), 0);
    const int stations = int(*stationsOption);
    const double minutes = *minutesOption;
    const int chunkMs = int(*chunkOption);
    std::vector<SimStation> sims;
    const model::WorkspaceFile file = startSimulators(sims, stations, chunkMs);
    if (file.lines.isEmpty())
        return 1;
    // Before the workspace takes the simulators over, so both see the same wires.
    QString floorError;
    const std::optional<WireFloor> floor =
        measureWireFloor(sims, kFloorSeconds * 1000, &floorError);
    if (!floor) {
        printError(floorError);
        return 1;
    }
    printFigure(QStringLiteral("fleet.floor_tx_per_s"), floor->txPerS, QStringLiteral("tx/s"));
    printFigure(QStringLiteral("fleet.floor_cpu_us_per_tx"), floor->cpuUsPerTx,
                QStringLiteral("us"));
    printFigure(QStringLiteral("fleet.floor_user_us_per_tx"), floor->userUsPerTx,
                QStringLiteral("us"));
    printFigure(QStringLiteral("fleet.floor_cpu_percent"), floor->cpuPercentAt(floor->txPerS),
                QStringLiteral("% of one core"));
    model::Workspace workspace;
    workspace.open(file);
    // For comparison: every line polled by its intervals only, as a single session is.
    const bool byIntervals = args.contains(QStringLiteral("--by-intervals"));
    for (int i = 0; byIntervals && i < workspace.count(); ++i)
        workspace.session(i)->scheduler().setFillWire(false);
    QElapsedTimer connecting;
    connecting.start();
    while (!allConnected(workspace) && connecting.elapsed() < kConnectMs)
        waitMs(200);
    if (!allConnected(workspace)) {
        for (int i = 0; i < workspace.count(); ++i)
            printError(QStringLiteral("%1: %2").arg(workspace.line(i).name,
                                                    workspace.session(i)->stateText()));
        return 1;
    }
    printFigure(QStringLiteral("fleet.connect_s"), double(connecting.elapsed()) / 1000,
                QStringLiteral("s"));
    gui::FleetPage page(workspace);
    page.resize(1920, 1080); // a wall display
    page.show();
    waitMs(kWarmupMs);
    printFigure(QStringLiteral("fleet.tiles"), page.tileCount(), QStringLiteral("tiles"), 0);
    page.clearTileLatencies();

    const Snapshot before = snapshot(workspace, sims);
    const EventTally events;
    const ProcessActivity activity(QCoreApplication::applicationPid());
    const qint64 allocationsBefore = allocationsSoFar();
    QElapsedTimer wall;
    wall.start();
    waitMs(int(minutes * 60000));
    const Snapshot after = snapshot(workspace, sims);
    const std::optional<qint64> syscalls = activity.syscalls();
    const qint64 wakeUps = activity.wakeUps();
    const qint64 allocations = allocationsSoFar() - allocationsBefore;
    const double seconds = double(wall.elapsed()) / 1000;
    const std::vector<double> latencies = page.tileLatenciesMs();

    printFigure(QStringLiteral("fleet.seconds"), seconds, QStringLiteral("s"));
    printFigure(QStringLiteral("fleet.gui_cpu_percent"),
                100.0 * double(after.cpuUs - before.cpuUs) / (seconds * 1e6),
                QStringLiteral("% of one core"));
    printFigure(QStringLiteral("fleet.sim_cpu_percent"),
                100.0 * double(after.simCpuUs - before.simCpuUs) / (seconds * 1e6),
                QStringLiteral("% of one core"));
    const double rate = printRates(workspace, before, after, seconds);
    const double usPerTx = rate > 0 ? double(after.cpuUs - before.cpuUs) / (rate * seconds) : 0;
    printFigure(QStringLiteral("fleet.cpu_us_per_tx"), usPerTx, QStringLiteral("us"));
    printFigure(QStringLiteral("fleet.floor_cpu_percent_at_fleet_rate"), floor->cpuPercentAt(rate),
                QStringLiteral("% of one core"));
    printFigure(QStringLiteral("fleet.cpu_over_floor"), usPerTx / floor->cpuUsPerTx, QString(), 2);
    // Where the time goes, per transaction, beside the floor's.
    const double transactions = rate * seconds;
    const auto perTx = [&](const char *name, double count) {
        printFigure(QStringLiteral("fleet.%1_per_tx").arg(QLatin1String(name)),
                    transactions > 0 ? count / transactions : 0, QString(), 2);
    };
    if (syscalls)
        perTx("syscalls", double(*syscalls));
    else
        printNote(QStringLiteral("fleet.syscalls_per_tx: not measured, %1")
                      .arg(activity.whyNoSyscalls()));
    if (floor->syscallsPerTx)
        printFigure(QStringLiteral("fleet.floor_syscalls_per_tx"), *floor->syscallsPerTx, QString(),
                    2);
    perTx("wakeups", double(wakeUps));
    printFigure(QStringLiteral("fleet.floor_wakeups_per_tx"), floor->wakeUpsPerTx, QString(), 2);
    perTx("timer_events", double(events.count(QEvent::Timer)));
    perTx("socket_events", double(events.count(QEvent::SockAct)));
    perTx("queued_calls", double(events.count(QEvent::MetaCall)));
    perTx("events", double(events.total()));
    perTx("cxx_allocations", double(allocations));
    ChannelRates rates{};
    for (size_t c = 0; c < rates.size(); ++c) {
        rates[c] = double(after.samples[c] - before.samples[c]) / seconds / stations;
        printFigure(QStringLiteral("fleet.%1_hz").arg(fleetChannelName(int(c))), rates[c],
                    QStringLiteral("Hz"), 2);
    }
    const QList<double> late(latencies.begin(), latencies.end());
    printFigure(QStringLiteral("fleet.tile_repaints"), double(late.size()),
                QStringLiteral("repaints"), 0);
    printFigure(QStringLiteral("fleet.tile_latency_ms_p50"), quantile(late, 0.5),
                QStringLiteral("ms"));
    printFigure(QStringLiteral("fleet.tile_latency_ms_p99"), quantile(late, 0.99),
                QStringLiteral("ms"));
    printFigure(QStringLiteral("fleet.rss_mb"), double(selfStatusBytes("VmRSS:")) / (1 << 20),
                QStringLiteral("MB"));
    workspace.close();
    sims.clear();
    printDayMemory(rates, stations, kDayHours);
    return 0;
}

} // namespace tipscope::bench
