#include "fleetlivebench.h"

#include "benchsupport.h"
#include "fleetday.h"

#include "model/workspace/workspace.h"
#include "pages/fleet/fleetpage.h"
#include "ptyfixtures.h"

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTextStream>
#include <csignal>
#include <memory>
#include <vector>

namespace tipscope::bench {

namespace {

constexpr int kPaceBaud = 19200;
constexpr double kWireBytesPerSecond = kPaceBaud / 10.0; // 8N1: ten bits per byte
constexpr int kConnectMs = 120000;
// Discovery, the first reading of every setting and the tips heating up stay out of the figures.
constexpr int kWarmupMs = 10000;
constexpr int kDayHours = 24;

// One simulated line: a tipscope-sim started detached, its address read from the file its
// standard output goes to. Detached, the simulator leaves no pipe or process handle in this
// process, whose event loop would otherwise poll three of them a line beside the line's socket:
// what is measured is what the application has, a socket a line.
class SimLine {
public:
    explicit SimLine(QString name)
        : m_name(std::move(name)) {}
    ~SimLine() {
        if (m_pid > 0)
            ::kill(pid_t(m_pid), SIGTERM);
    }
    SimLine(const SimLine &) = delete;
    SimLine &operator=(const SimLine &) = delete;

    // Starts the simulator and returns the address it serves, or empty with `error` set.
    [[nodiscard]] QString start(const QStringList &args, QString *error) {
        const QString out = m_dir.filePath(QStringLiteral("out"));
        QProcess process;
        process.setProgram(testing::binaryPath(QStringLiteral("tipscope-sim")));
        process.setArguments(args);
        process.setStandardOutputFile(out);
        process.setStandardErrorFile(m_dir.filePath(QStringLiteral("err")));
        if (!m_dir.isValid() || !process.startDetached(&m_pid)) {
            *error = QStringLiteral("tipscope-sim did not start");
            return {};
        }
        QFile file(out);
        QElapsedTimer waited;
        waited.start();
        while (waited.elapsed() < 10000) {
            if (file.open(QIODevice::ReadOnly | QIODevice::Text)) {
                const QByteArray first = file.readLine();
                file.close();
                if (first.endsWith('\n'))
                    return QString::fromLocal8Bit(first).trimmed();
            }
            waitMs(50);
        }
        *error = QStringLiteral("tipscope-sim printed no address");
        return {};
    }
    [[nodiscard]] const QString &name() const { return m_name; }
    [[nodiscard]] qint64 pid() const { return m_pid; }

private:
    QString m_name;
    QTemporaryDir m_dir;
    qint64 m_pid = 0;
};

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
model::WorkspaceFile startSimulators(std::vector<std::unique_ptr<SimLine>> &sims, int stations,
                                     int chunkMs) {
    const QStringList args = {QStringLiteral("--model"),  QStringLiteral("DME"),
                              QStringLiteral("--feeder"), QStringLiteral("--activity"),
                              QStringLiteral("--tcp"),    QStringLiteral("127.0.0.1:0"),
                              QStringLiteral("--pace"),   QString::number(kPaceBaud),
                              QStringLiteral("--chunk"),  QString::number(chunkMs)};
    model::WorkspaceFile file;
    for (int i = 0; i < stations; ++i) {
        auto line =
            std::make_unique<SimLine>(QStringLiteral("line%1").arg(i + 1, 2, 10, QLatin1Char('0')));
        QString error;
        const QString where = line->start(args, &error);
        if (where.isEmpty()) {
            printError(QStringLiteral("%1: %2").arg(line->name(), error));
            return {};
        }
        file.lines.append(tcpLine(line->name(), where));
        sims.push_back(std::move(line));
    }
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

Snapshot snapshot(const model::Workspace &workspace,
                  const std::vector<std::unique_ptr<SimLine>> &sims) {
    Snapshot s;
    for (int i = 0; i < workspace.count(); ++i) {
        model::Session &session = *workspace.session(i);
        const link::LinkStats &stats = session.line()->queue().stats();
        s.lines.push_back({stats.answered, stats.sentBytes + stats.receivedBytes});
        const auto samples = channelSamples(session.telemetry());
        for (size_t c = 0; c < samples.size(); ++c)
            s.samples[c] += samples[c];
    }
    for (const auto &line : sims)
        s.simCpuUs += processCpuUs(line->pid()).value_or(0);
    s.cpuUs = selfCpuUs();
    return s;
}

// The lines' rates against their wires' limits; returns the achieved transactions a second.
double printRates(const model::Workspace &workspace, const Snapshot &before, const Snapshot &after,
                  double seconds) {
    double rateSum = 0, limitSum = 0;
    for (int i = 0; i < workspace.count(); ++i) {
        const qint64 answered = after.lines[size_t(i)].answered - before.lines[size_t(i)].answered;
        const qint64 bytes = after.lines[size_t(i)].bytes - before.lines[size_t(i)].bytes;
        const double rate = double(answered) / seconds;
        // The paced wire's bytes a second over this line's own bytes per transaction.
        const double limit =
            answered > 0 && bytes > 0 ? kWireBytesPerSecond * double(answered) / double(bytes) : 0;
        const QString line = workspace.line(i).name;
        printFigure(QStringLiteral("fleet.%1_tx_per_s").arg(line), rate, QStringLiteral("tx/s"));
        printFigure(QStringLiteral("fleet.%1_wire_limit_tx_per_s").arg(line), limit,
                    QStringLiteral("tx/s"));
        rateSum += rate;
        limitSum += limit;
    }
    printFigure(QStringLiteral("fleet.tx_per_s"), rateSum, QStringLiteral("tx/s"));
    printFigure(QStringLiteral("fleet.wire_limit_tx_per_s"), limitSum, QStringLiteral("tx/s"));
    printFigure(QStringLiteral("fleet.rate_ratio"), limitSum > 0 ? rateSum / limitSum : 0,
                QString(), 3);
    return rateSum;
}

} // namespace

int runFleetLiveBench(const QStringList &args) {
    if (args.contains(QStringLiteral("--help")) || args.contains(QStringLiteral("-h"))) {
        QTextStream(stdout)
            << "Usage: tipscope-bench fleet [--stations N] [--minutes M] [--chunk-ms C] "
               "[--by-intervals]\n"
               "N simulated lines (default 32; a DME and a feeder each, TCP, paced at 19200 "
               "baud)\n"
               "in one workspace with the fleet overview shown, measured for M minutes (default "
               "10,\n"
               "fractions allowed): CPU, transactions against the wire limit, tile latency, and "
               "the\n"
               "memory of a day of the fleet at the sample rates achieved. --by-intervals polls\n"
               "each line by its intervals only instead of filling its wire. --chunk-ms hands\n"
               "each answer over in chunks every C ms, as a USB adapter or a device server does\n"
               "(default 0: a byte at a time, the most wake-ups).\n";
        return 0;
    }
    const int stations = qMax(1, optionValue(args, "--stations", QStringLiteral("32")).toInt());
    const double minutes = optionValue(args, "--minutes", QStringLiteral("10")).toDouble();
    if (minutes <= 0) {
        printError(QStringLiteral("--minutes takes a positive number"));
        return 1;
    }

    const int chunkMs = qMax(0, optionValue(args, "--chunk-ms", QStringLiteral("0")).toInt());
    std::vector<std::unique_ptr<SimLine>> sims;
    const model::WorkspaceFile file = startSimulators(sims, stations, chunkMs);
    if (file.lines.isEmpty())
        return 1;
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
    QElapsedTimer wall;
    wall.start();
    waitMs(int(minutes * 60000));
    const Snapshot after = snapshot(workspace, sims);
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
    printFigure(QStringLiteral("fleet.cpu_us_per_tx"),
                rate > 0 ? double(after.cpuUs - before.cpuUs) / (rate * seconds) : 0,
                QStringLiteral("us"));
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
