#include "soakbench.h"

#include "benchsupport.h"
#include "linkdriver.h"
#include "soakreport.h"

#include "model/device/stationmodel.h"
#include "model/live/pollscheduler.h"
#include "protocol/valuecodec.h"

#include <QEventLoop>
#include <QFile>
#include <QTemporaryDir>
#include <functional>

namespace tipscope::bench {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {

const QList<QByteArray> kCodes = {"ST1", "ST2", "ST3", "ST4", "A11", "A21", "A31", "A41"};
constexpr int kOpenTimeoutMs = 10000;
constexpr int kDrainTimeoutMs = 60000;
constexpr int kRecoveryTimeoutMs = 20000;
constexpr int kQuietEndMs = 15000; // no unplug this close to the end: let the last one recover

struct Options {
    double minutes = 3;
    int unplugEverySec = 60;
    int seed = 1;
    int pace = 19200;
    int inFlight = 2;
};

bool waitUntil(const std::function<bool()> &done, int timeoutMs) {
    if (done())
        return true;
    QElapsedTimer clock;
    clock.start();
    QEventLoop loop;
    QTimer poll;
    poll.setInterval(10);
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done() || clock.elapsed() >= timeoutMs)
            loop.quit();
    });
    poll.start();
    loop.exec();
    return done();
}

// VmRSS or VmHWM of a process, in KiB, from /proc; -1 when unreadable.
qint64 procStatusKiB(const QString &pid, const QByteArray &field) {
    QFile f(QStringLiteral("/proc/%1/status").arg(pid));
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return -1;
    for (QByteArray line = f.readLine(); !line.isEmpty(); line = f.readLine())
        if (line.startsWith(field + ':'))
            return line.mid(field.size() + 1).trimmed().split(' ').value(0).toLongLong();
    return -1;
}

std::optional<Options> parseOptions(const QStringList &args) {
    Options o;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString a = args.at(i);
        bool ok = i + 1 < args.size();
        const QString v = ok ? args.at(++i) : QString();
        if (a == QLatin1String("--minutes"))
            o.minutes = v.toDouble(&ok), ok = ok && o.minutes >= 0.25 && o.minutes <= 600;
        else if (a == QLatin1String("--unplug-every"))
            o.unplugEverySec = v.toInt(&ok), ok = ok && o.unplugEverySec >= 5;
        else if (a == QLatin1String("--seed"))
            o.seed = v.toInt(&ok), ok = ok && o.seed >= 0;
        else if (a == QLatin1String("--pace"))
            o.pace = v.toInt(&ok), ok = ok && o.pace >= 1200;
        else if (a == QLatin1String("--writes-in-flight"))
            o.inFlight = v.toInt(&ok), ok = ok && o.inFlight >= 1 && o.inFlight <= 8;
        else
            ok = false;
        if (!ok)
            return std::nullopt;
    }
    return o;
}

class Soak {
public:
    explicit Soak(const Options &o)
        : m_o(o) {}
    [[nodiscard]] bool setUp(QString *error);
    void run();
    void finish();
    [[nodiscard]] const SoakResult &result() const { return m_r; }

private:
    std::optional<SimStats> simStats();
    // What the device holds, from the simulator past the line: every stored setting, or `codes`.
    std::optional<QMap<QByteArray, qint64>> deviceSettings(const QByteArray &codes = {});
    void probeDevice(const QByteArray &code,
                     const std::function<void(std::optional<qint64>)> &done);
    void checkEveryCode();
    void unplugOnce();

    Options m_o;
    QTemporaryDir m_dir;
    testing::SimProcess m_sim;
    std::unique_ptr<SimConsole> m_console;
    std::unique_ptr<Line> m_line;
    std::unique_ptr<model::StationModel> m_station;
    model::PollScheduler m_scheduler;
    std::unique_ptr<FaultWindows> m_faults;
    std::unique_ptr<WriteStream> m_writes;
    QMap<QByteArray, qint64> m_initial; // every stored setting before the first write
    QElapsedTimer m_clock;
    SoakResult m_r;
};

bool Soak::setUp(QString *error) {
    const QString link = m_dir.filePath(QStringLiteral("station"));
    const QString pct = QStringLiteral("0.01");
    const QString half = QStringLiteral("0.005");
    if (m_sim
            .start({"--model", "DME", "--pty", "--link", link, "--pace", QString::number(m_o.pace),
                    "--drop", pct, "--corrupt", pct, "--garbage", pct, "--drop-requests", half,
                    "--corrupt-requests", half, "--seed", QString::number(m_o.seed)},
                   error)
            .isEmpty())
        return false;
    m_console = std::make_unique<SimConsole>(m_sim.process());
    LineSettings settings;
    settings.serial.portName = link;
    m_line = std::make_unique<Line>(Line::makeTransport(settings, nullptr), settings);
    m_line->open();
    if (!waitUntil([this] { return m_line->state() == Line::State::Open; }, kOpenTimeoutMs)) {
        *error = QStringLiteral("cannot open %1: %2").arg(link, m_line->stateText());
        return false;
    }
    DeviceInfo info;
    info.address = 1;
    info.model = QStringLiteral("DME-2C");
    info.family = QStringLiteral("DME");
    m_station = std::make_unique<model::StationModel>(m_line->queue(), info);
    m_writes = std::make_unique<WriteStream>(
        *m_station, kCodes, quint32(m_o.seed),
        [this](const QByteArray &code, const std::function<void(std::optional<qint64>)> &done) {
            probeDevice(code, done);
        });
    const auto initial = deviceSettings();
    if (!initial || !std::all_of(kCodes.begin(), kCodes.end(),
                                 [&](const QByteArray &c) { return initial->contains(c); })) {
        *error = QStringLiteral("cannot read the device's settings before the soak");
        return false;
    }
    m_initial = *initial;
    for (const QByteArray &code : kCodes)
        m_writes->setInitial(code, m_initial.value(code));
    m_faults = std::make_unique<FaultWindows>(*m_console, 0.005, 0.005, m_o.pace);
    return true;
}

void Soak::run() {
    m_scheduler.addDevice(m_station.get());
    m_scheduler.setVisiblePorts(m_station.get(), {1, 2, 3, 4});
    m_scheduler.start();
    runEventLoopFor(2000); // the first poll round, so RSS at start includes the models' data
    m_r.rssStartKiB = procStatusKiB(QStringLiteral("self"), "VmRSS");
    m_r.simRssStartKiB = procStatusKiB(QString::number(m_sim.process().processId()), "VmRSS");
    m_clock.start();
    m_faults->start();
    m_writes->start(m_o.inFlight);
    const qint64 endMs = qint64(m_o.minutes * 60000);
    const qint64 every = qint64(m_o.unplugEverySec) * 1000;
    qint64 nextUnplug = qMin(every, endMs / 2); // even a short run unplugs once
    while (m_clock.elapsed() < endMs) {
        const bool unplugDue = nextUnplug + kQuietEndMs < endMs;
        const qint64 until = unplugDue ? nextUnplug : endMs;
        runEventLoopFor(int(qMax<qint64>(0, until - m_clock.elapsed())));
        if (unplugDue) {
            unplugOnce();
            nextUnplug += every;
        }
    }
}

void Soak::unplugOnce() {
    m_faults->setPaused(true);
    waitUntil([this] { return !m_faults->windowOpen(); }, 2000);
    auto u = std::make_shared<SoakUnplug>();
    auto since = std::make_shared<QElapsedTimer>();
    auto reply = std::make_shared<QString>();
    const auto watch = QObject::connect(m_line.get(), &Line::stateChanged, m_line.get(),
                                        [u, since](Line::State s) {
                                            if (s == Line::State::Retrying && u->detectMs < 0)
                                                u->detectMs = since->elapsed();
                                        });
    since->start();
    m_console->send(QStringLiteral("unplug"), [reply](const QString &r) { *reply = r; });
    waitUntil([reply] { return !reply->isEmpty(); }, 5000);
    runEventLoopFor(1000);
    reply->clear();
    m_console->send(QStringLiteral("plug"), [reply](const QString &r) { *reply = r; });
    waitUntil([reply] { return !reply->isEmpty(); }, 5000);
    QElapsedTimer plugged;
    plugged.start();
    const qint64 answered = m_line->queue().stats().answered;
    if (waitUntil([&] { return m_line->queue().stats().answered > answered; }, kRecoveryTimeoutMs))
        u->recoveryMs = plugged.elapsed();
    QObject::disconnect(watch);
    m_r.unplugs.append(*u);
    m_faults->setPaused(false);
}

std::optional<SimStats> Soak::simStats() {
    auto reply = std::make_shared<QString>();
    m_console->send(QStringLiteral("stats"), [reply](const QString &r) { *reply = r; });
    waitUntil([reply] { return !reply->isEmpty(); }, 5000);
    return SimStats::parse(*reply);
}

std::optional<QMap<QByteArray, qint64>> Soak::deviceSettings(const QByteArray &codes) {
    auto reply = std::make_shared<QString>();
    m_console->send(QStringLiteral("get %1").arg(QString::fromLatin1(codes)).trimmed(),
                    [reply](const QString &r) { *reply = r; });
    waitUntil([reply] { return !reply->isEmpty(); }, 5000);
    return parseSettings(*reply);
}

void Soak::probeDevice(const QByteArray &code,
                       const std::function<void(std::optional<qint64>)> &done) {
    m_console->send(
        QStringLiteral("get ") + QString::fromLatin1(code), [code, done](const QString &reply) {
            const auto held = parseSettings(reply);
            done(held && held->contains(code) ? std::optional(held->value(code)) : std::nullopt);
        });
}

// Every setting the device stores: the written codes as the ledger allows, the others as they
// were before the first write (a write that went astray would show here).
void Soak::checkEveryCode() {
    const auto now = deviceSettings().value_or(QMap<QByteArray, qint64>());
    for (auto it = m_initial.cbegin(); it != m_initial.cend(); ++it) {
        const QByteArray &code = it.key();
        ++m_r.codes;
        if (!now.contains(code)) {
            ++m_r.unreadable;
            continue;
        }
        const qint64 v = now.value(code);
        const WriteStream::Verdict verdict = kCodes.contains(code) ? m_writes->judge(code, v)
                                             : v == it.value()     ? WriteStream::Verdict::Expected
                                                               : WriteStream::Verdict::Unexpected;
        if (verdict == WriteStream::Verdict::FromFailedWrite) {
            ++m_r.fromFailedWrite;
            printNote(QStringLiteral("%1 holds %2, written by a write reported failed: %3")
                          .arg(QString::fromLatin1(code))
                          .arg(v)
                          .arg(m_writes->failureReason(code, v)));
        }
        if (verdict == WriteStream::Verdict::Unexpected) {
            ++m_r.unexpected;
            printNote(QStringLiteral("%1 holds %2; %3")
                          .arg(QString::fromLatin1(code))
                          .arg(v)
                          .arg(kCodes.contains(code)
                                   ? m_writes->expectationText(code)
                                   : QStringLiteral("never written, was %1").arg(it.value())));
        }
    }
}

void Soak::finish() {
    m_r.seconds = m_clock.elapsed() / 1000.0;
    m_writes->stopIssuing();
    m_faults->stop();
    waitUntil([this] { return !m_faults->windowOpen(); }, 2000);
    waitUntil([this] { return m_writes->busy() == 0; }, kDrainTimeoutMs);
    m_scheduler.stop();
    waitUntil([this] { return m_line->queue().pendingCount() == 0; }, kDrainTimeoutMs);
    m_r.pendingAfterDrain = m_line->queue().pendingCount();
    m_r.link = m_line->queue().stats();
    m_r.lineReconnects = m_line->reconnects();
    m_r.polls = m_scheduler.pollsDone();
    m_r.sim = simStats().value_or(SimStats());
    m_r.nakInjected = m_faults->naked();
    m_r.delayInjected = m_faults->delayed();
    m_r.nakWindows = m_faults->nakWindows();
    m_r.delayWindows = m_faults->delayWindows();
    m_r.writes = m_writes->tally();
    m_r.lost = m_writes->outstanding();
    checkEveryCode();
    m_r.pendingAtEnd = m_line->queue().pendingCount();
    m_r.rssEndKiB = procStatusKiB(QStringLiteral("self"), "VmRSS");
    m_r.rssPeakKiB = procStatusKiB(QStringLiteral("self"), "VmHWM");
    m_r.simRssEndKiB = procStatusKiB(QString::number(m_sim.process().processId()), "VmRSS");
}

} // namespace

int runSoakBench(const QStringList &args) {
    if (args.contains(QStringLiteral("--help")) || args.contains(QStringLiteral("-h"))) {
        printNote(QStringLiteral(
            "usage: tipscope-bench soak [--minutes N (3)] [--unplug-every S (60)] [--seed N (1)] "
            "[--pace BAUD (19200)] [--writes-in-flight N (2)]"));
        return 0;
    }
    const auto options = parseOptions(args);
    if (!options) {
        printError(QStringLiteral("soak: bad arguments (see tipscope-bench soak --help)"));
        return 1;
    }
    Soak soak(*options);
    QString error;
    if (!soak.setUp(&error)) {
        printError(QStringLiteral("soak: ") + error);
        return 1;
    }
    printFigure(QStringLiteral("soak.minutes"), options->minutes, QStringLiteral("min"), 2);
    printFigure(QStringLiteral("soak.pace"), options->pace, QStringLiteral("baud"), 0);
    printFigure(QStringLiteral("soak.seed"), options->seed, QString(), 0);
    soak.run();
    soak.finish();
    return printSoakReport(soak.result()) ? 0 : 1;
}

} // namespace tipscope::bench
