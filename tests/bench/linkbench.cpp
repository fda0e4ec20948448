#include "linkbench.h"

#include "benchsupport.h"
#include "linkdriver.h"

#include "link/discovery.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTextStream>
#include <QTimer>
#include <algorithm>

namespace tipscope::bench {

using namespace tipscope::link;

namespace {

constexpr int kDefaultSeconds = 3;
constexpr int kDefaultTurnaroundMs = 100;
constexpr int kStation = 1;
constexpr int kPolledPorts = 4;
constexpr int kWriteIntervalMs = 150;
constexpr int kMinWrites = 100;
constexpr int kDetectRuns = 3;
constexpr int kDetectTimeoutMs = 10000;

struct Options {
    int seconds = kDefaultSeconds;
    int turnaroundMs = kDefaultTurnaroundMs;
};

QStringList simArgs(bool paced, bool feeder) {
    QStringList a = {QStringLiteral("--model"), QStringLiteral("DME"), QStringLiteral("--pty")};
    if (feeder)
        a << QStringLiteral("--feeder");
    if (paced)
        a << QStringLiteral("--pace") << QString::number(kPaceBaud);
    return a;
}

bool startLink(SimLink &link, const QStringList &args, const Options &o, const char *phase) {
    QString error;
    if (link.start(args, o.turnaroundMs, &error))
        return true;
    printError(QStringLiteral("%1 phase: %2").arg(QLatin1String(phase), error));
    return false;
}

double bytesPerTransaction(const TrafficCounts &c) {
    return double(c.requestBytes + c.answerBytes) / double(qMax<qint64>(1, c.ok));
}

void checkTarget(bool met, const QString &what) {
    if (!met)
        printNote(QStringLiteral("target missed: ") + what);
}

QList<Request> alternateTt1Pp1() {
    return {Request::read(kStation, "TT1"), Request::read(kStation, "PP1")};
}

bool pacedPhase(const Options &o) {
    SimLink link;
    if (!startLink(link, simArgs(true, false), o, "paced"))
        return false;
    ReadLoop loop(link.queue());
    loop.addChain(alternateTt1Pp1());
    const auto w = measure(link, loop, o.seconds, "paced");
    if (!w)
        return false;
    const double rate = double(w->counts.ok) / w->seconds;
    const double limit = kWireBytesPerSecond / bytesPerTransaction(w->counts);
    printFigure(QStringLiteral("link.paced_tx_per_s"), rate, QStringLiteral("tx/s"));
    printFigure(QStringLiteral("link.wire_limit_tx_per_s"), limit, QStringLiteral("tx/s"));
    printFigure(QStringLiteral("link.paced_ratio"), 100.0 * rate / limit,
                QStringLiteral("% of the wire limit"));
    checkTarget(rate >= 0.95 * limit, QStringLiteral("paced rate below 95% of the wire limit"));
    return true;
}

bool unpacedPhase(const Options &o) {
    SimLink link;
    if (!startLink(link, simArgs(false, false), o, "unpaced"))
        return false;
    ReadLoop loop(link.queue());
    loop.addChain(alternateTt1Pp1());
    const auto w = measure(link, loop, o.seconds, "unpaced");
    if (!w)
        return false;
    const double rate = double(w->counts.ok) / w->seconds;
    const double tx = double(w->counts.ok);
    printFigure(QStringLiteral("link.unpaced_tx_per_s"), rate, QStringLiteral("tx/s"));
    printFigure(QStringLiteral("link.cpu_us_per_tx"), double(w->cpuUs) / tx, QStringLiteral("us"));
    if (w->simCpuUs)
        printFigure(QStringLiteral("link.sim_cpu_us_per_tx"), double(*w->simCpuUs) / tx,
                    QStringLiteral("us"));
    checkTarget(rate >= 2000, QStringLiteral("unpaced rate below 2000 tx/s"));
    return true;
}

bool polledPhase(const Options &o) {
    SimLink link;
    if (!startLink(link, simArgs(true, false), o, "polled"))
        return false;
    ReadLoop poll(link.queue());
    for (int port = 1; port <= kPolledPorts; ++port)
        for (const char *c : {"TT", "PP", "PS"})
            poll.addChain(
                {Request::read(kStation, c + QByteArray::number(port), Priority::LivePoll)});
    poll.start();
    runEventLoopFor(kWarmupMs);
    poll.resetCounts();
    WriteProbe probe(link.queue(), Request::write(kStation, "ST1", "00350"),
                     Request::write(kStation, "ST1", "00355"), kWriteIntervalMs);
    QElapsedTimer clock;
    clock.start();
    runUntilEnoughWrites(probe, kMinWrites, o.seconds, 3 * kMinWrites * kWriteIntervalMs);
    const double seconds = double(clock.nsecsElapsed()) / 1e9;
    const TrafficCounts pollCounts = poll.counts();
    poll.stop();
    const QList<double> &lat = probe.latenciesMs();
    if (lat.isEmpty() || pollCounts.ok == 0) {
        printError(QStringLiteral("polled phase: no write finished (%1) or no poll answered (%2)")
                       .arg(probe.counts().firstError, pollCounts.firstError));
        return false;
    }
    if (probe.counts().failed + pollCounts.failed > 0)
        printNote(QStringLiteral("polled phase: %1 write(s) and %2 poll(s) failed: %3")
                      .arg(probe.counts().failed)
                      .arg(pollCounts.failed)
                      .arg(probe.counts().firstError + pollCounts.firstError));
    // What an ideal queue costs at worst: a whole read already on the wire, then the write.
    const double floorMs = 1000.0 *
                           (bytesPerTransaction(pollCounts) + bytesPerTransaction(probe.counts())) /
                           kWireBytesPerSecond;
    const double p99 = quantile(lat, 0.99);
    printFigure(QStringLiteral("link.write_count"), double(lat.size()), QStringLiteral("writes"),
                0);
    printFigure(QStringLiteral("link.write_p50_ms"), quantile(lat, 0.5), QStringLiteral("ms"));
    printFigure(QStringLiteral("link.write_p99_ms"), p99, QStringLiteral("ms"));
    printFigure(QStringLiteral("link.write_max_ms"), *std::max_element(lat.begin(), lat.end()),
                QStringLiteral("ms"));
    printFigure(QStringLiteral("link.write_floor_ms"), floorMs, QStringLiteral("ms"));
    printFigure(QStringLiteral("link.poll_tx_per_s"), double(pollCounts.ok) / seconds,
                QStringLiteral("tx/s"));
    checkTarget(p99 <= 40, QStringLiteral("write p99 above 40 ms"));
    return true;
}

bool detectPhase(const Options &o) {
    SimLink link;
    if (!startLink(link, simArgs(false, true), o, "detect"))
        return false;
    QList<double> times;
    qsizetype devices = -1;
    for (int run = 0; run < kDetectRuns; ++run) {
        Discovery discovery(link.queue());
        QEventLoop wait;
        bool finished = false;
        QObject::connect(&discovery, &Discovery::finished, &wait, [&] {
            finished = true;
            wait.quit();
        });
        QTimer::singleShot(kDetectTimeoutMs, &wait, &QEventLoop::quit);
        QElapsedTimer clock;
        clock.start();
        discovery.start();
        wait.exec();
        if (!finished) {
            printError(QStringLiteral("detect phase: discovery did not finish in %1 ms")
                           .arg(kDetectTimeoutMs));
            return false;
        }
        times.append(double(clock.nsecsElapsed()) / 1e6);
        if (devices >= 0 && devices != discovery.devices().size())
            printNote(QStringLiteral("detect phase: the runs found different device counts"));
        devices = discovery.devices().size();
    }
    if (devices == 0) {
        printError(QStringLiteral("detect phase: no device found on %1").arg(link.path()));
        return false;
    }
    const double median = quantile(times, 0.5);
    printFigure(QStringLiteral("link.detect_ms"), median, QStringLiteral("ms"));
    printFigure(QStringLiteral("link.detect_devices"), double(devices), QStringLiteral("devices"),
                0);
    checkTarget(median < 1000, QStringLiteral("detection took 1 s or more"));
    return true;
}

// Returns -1 to go on, or the exit status to end with (0 after --help).
int parseOptions(const QStringList &args, Options *o) {
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral("Link throughput, write latency and detection "
                                               "time against tipscope-sim on a PTY."));
    p.addOptions({
        {QStringLiteral("seconds"), QStringLiteral("Measured time per phase (default 3)."),
         QStringLiteral("N")},
        {QStringLiteral("turnaround"),
         QStringLiteral("Device turnaround of the queue's answer budget (default 100)."),
         QStringLiteral("MS")},
        {{QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Show this help.")},
    });
    // QCommandLineParser names the program from argv[0]; the subcommand belongs in the usage.
    const QString help = QStringLiteral("Usage: tipscope-bench link [options]\n") +
                         p.helpText().section(QLatin1Char('\n'), 1);
    if (!p.parse(QStringList{QStringLiteral("tipscope-bench link")} + args) ||
        !p.positionalArguments().isEmpty()) {
        printError(p.errorText().isEmpty() ? QStringLiteral("unexpected arguments")
                                           : p.errorText());
        printNote(help);
        return 1;
    }
    if (p.isSet(QStringLiteral("help"))) {
        QTextStream(stdout) << help;
        return 0;
    }
    bool ok = true;
    if (p.isSet(QStringLiteral("seconds")))
        o->seconds = p.value(QStringLiteral("seconds")).toInt(&ok);
    if (!ok || o->seconds < 1 || o->seconds > 3600) {
        printError(QStringLiteral("--seconds takes a whole number from 1 to 3600"));
        return 1;
    }
    if (p.isSet(QStringLiteral("turnaround")))
        o->turnaroundMs = p.value(QStringLiteral("turnaround")).toInt(&ok);
    if (!ok || o->turnaroundMs < 1 || o->turnaroundMs > 60'000) {
        printError(QStringLiteral("--turnaround takes a whole number of ms from 1 to 60000"));
        return 1;
    }
    return -1;
}

} // namespace

int runLinkBench(const QStringList &args) {
    Options o;
    if (const int status = parseOptions(args, &o); status >= 0)
        return status;
    printFigure(QStringLiteral("link.seconds_per_phase"), o.seconds, QStringLiteral("s"), 0);
    printFigure(QStringLiteral("link.turnaround_ms"), o.turnaroundMs, QStringLiteral("ms"), 0);
    for (bool (*phase)(const Options &) : {pacedPhase, unpacedPhase, polledPhase, detectPhase})
        if (!phase(o))
            return 1;
    return 0;
}

} // namespace tipscope::bench
