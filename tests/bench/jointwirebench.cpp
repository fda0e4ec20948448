#include "jointwirebench.h"

#include "agentprocess.h"
#include "benchsupport.h"
#include "jointscore.h"
#include "journal/journalreader.h"
#include "link/line.h"
#include "link/simtransport.h"
#include "model/appsettings.h"
#include "model/device/stationmodel.h"
#include "model/joints/jointwatcher.h"
#include "model/live/pollscheduler.h"
#include "model/live/telemetryrecorder.h"
#include "model/telemetry/telemetry.h"
#include "mosquittobroker.h"
#include "ptyfixtures.h"
#include "sim/simline.h"
#include "simstations.h"
#include "wireuse.h"

#include <QDateTime>
#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <csignal>
#include <memory>

namespace tipscope::bench {

using namespace tipscope::model;

namespace {
constexpr int kBaud = 19200;
constexpr int kChunkMs = 8;
// Every front end is counted from this long after it started: the station's tips heat up
// (about 10 s) and a joint is looked for only once a tip has stayed in its band for 2 s, as a
// heat-up's ringing cannot be told from a joint (docs/joints.md); the simulator makes its first
// joints as soon as the tips are at their temperature.
constexpr qint64 kWarmUpMs = 15'000;

const QStringList kFrontEnds = {QStringLiteral("core"), QStringLiteral("core_fixed"),
                                QStringLiteral("cli"), QStringLiteral("cli_5000"),
                                QStringLiteral("agent")};

struct Options {
    double minutes = 10;
    double perMinute = 12;
    quint32 seed = 1;
    QStringList sets = sim::JointShapeSet::names();
    QStringList frontEnds = kFrontEnds;
};

// One front end on one shape set.
class Run {
public:
    virtual ~Run() = default;
    [[nodiscard]] virtual bool start(QString *error) = 0;
    virtual void stop() = 0;
    [[nodiscard]] virtual QList<JointFigure> figures() = 0;
};

// The session's classes in this process, on a simulated station of its own.
class CoreRun : public Run {
public:
    CoreRun(const Options &o, const sim::JointShapeSet &shapes, bool adaptive, QString label)
        : m_label(std::move(label))
        , m_recorder(m_telemetry, [] { return QDateTime::currentMSecsSinceEpoch(); })
        , m_watcher(m_telemetry) {
        m_sim.addDevice(std::make_unique<sim::SimStation>(QStringLiteral("DME"), 1));
        m_sim.setBaud(kBaud);
        m_sim.setChunkMs(kChunkMs);
        m_sim.setRandomJoints(o.perMinute, o.seed, shapes);
        QObject::connect(&m_sim, &sim::SimLine::jointMade,
                         [this](const sim::SimJoint &j) { m_truth.made(j); });
        QObject::connect(&m_sim, &sim::SimLine::jointEnded,
                         [this](const sim::SimJoint &j) { m_truth.ended(j); });
        link::LineSettings settings;
        settings.kind = link::LineSettings::Kind::Demo;
        m_line =
            std::make_unique<link::Line>(std::make_unique<link::SimTransport>(m_sim), settings);
        const sim::SimDevice &d = *m_sim.devices().first();
        link::DeviceInfo info;
        info.address = d.address();
        info.model = d.modelName();
        info.family = d.family().name;
        info.softwareVersion = d.softwareVersion();
        m_station = std::make_unique<StationModel>(m_line->queue(), info);
        m_recorder.watch(m_station.get());
        StationModel *station = m_station.get();
        m_watcher.watch(station,
                        [station](int port) { return TelemetryRecorder::keyOf(*station, port); });
        QObject::connect(&m_watcher, &JointWatcher::jointEnded,
                         [this](const JointRecord &j) { m_found.append(j); });
        m_scheduler.addDevice(station);
        m_scheduler.setVisiblePorts(station, {1, 2, 3, 4});
        m_scheduler.setInterval(PollClass::Live, AppSettings{}.liveMs);
        m_scheduler.setInterval(PollClass::Status, AppSettings{}.statusMs);
        m_scheduler.setAdaptive(adaptive);
        m_wire = std::make_unique<WireUse>(*m_line, *station, m_scheduler, kBaud / 10.0);
    }

    bool start(QString *) override {
        m_line->open();
        m_sim.setClockRunning(true);
        m_scheduler.start();
        m_wire->start();
        m_startMs = QDateTime::currentMSecsSinceEpoch();
        return true;
    }

    void stop() override {
        m_scheduler.stop();
        m_wire->stop();
        m_endMs = QDateTime::currentMSecsSinceEpoch();
    }

    QList<JointFigure> figures() override {
        QList<JointFigure> f =
            scoreJoints(m_truth, m_found, m_startMs + kWarmUpMs, m_endMs, m_label);
        const QList<double> periods = tipPeriods();
        const double seconds = double(m_endMs - m_startMs) / 1000;
        f.append(
            {QStringLiteral("tip_period_p50_ms"), quantile(periods, 0.5), QStringLiteral("ms"), 0});
        f.append({QStringLiteral("tip_period_p95_ms"), quantile(periods, 0.95),
                  QStringLiteral("ms"), 0});
        f.append({QStringLiteral("polls_per_s"),
                  seconds > 0 ? double(m_scheduler.pollsDone()) / seconds : 0,
                  QStringLiteral("polls/s"), 1});
        f.append(m_wire->figures());
        printNote(QStringLiteral("%1: the wire while a port is busy: %2")
                      .arg(m_label, m_wire->breakdown()));
        return f;
    }

private:
    [[nodiscard]] QList<double> tipPeriods() const {
        QList<double> periods;
        for (int port = 1; port <= 4; ++port) {
            const TelemetryBuffer *b =
                m_telemetry.buffer(TelemetryRecorder::keyOf(*m_station, port));
            if (!b || b->isEmpty())
                continue;
            const auto tips = b->samples(b->seriesIndex(QStringLiteral("tip")), b->firstTime(),
                                         b->lastTime() + 1);
            for (qsizetype i = 1; i < tips.size(); ++i)
                periods.append(double(tips.at(i).timeMs - tips.at(i - 1).timeMs));
        }
        return periods;
    }

    QString m_label;
    sim::SimLine m_sim;
    std::unique_ptr<link::Line> m_line;
    std::unique_ptr<StationModel> m_station;
    Telemetry m_telemetry;
    TelemetryRecorder m_recorder;
    JointWatcher m_watcher;
    PollScheduler m_scheduler;
    std::unique_ptr<WireUse> m_wire;
    JointTruth m_truth;
    QList<JointRecord> m_found;
    qint64 m_startMs = 0;
    qint64 m_endMs = 0;
};

// A front end in a process of its own on a tipscope-sim of its own, its joints read back from
// its journal once it stopped.
class ProcessRun : public Run {
public:
    enum class Kind { Cli, CliSlow, Agent };

    ProcessRun(const Options &o, const sim::JointShapeSet &shapes, Kind kind, int brokerPort,
               QString label)
        : m_kind(kind)
        , m_brokerPort(brokerPort)
        , m_label(std::move(label))
        , m_sim(m_label)
        , m_simArgs{QStringLiteral("--model"),
                    QStringLiteral("DME"),
                    QStringLiteral("--tcp"),
                    QStringLiteral("127.0.0.1:0"),
                    QStringLiteral("--pace"),
                    QString::number(kBaud),
                    QStringLiteral("--chunk"),
                    QString::number(kChunkMs),
                    QStringLiteral("--joints-per-minute"),
                    QString::number(qRound(o.perMinute)),
                    QStringLiteral("--joint-shapes"),
                    shapes.name,
                    QStringLiteral("--seed"),
                    QString::number(o.seed)} {}

    bool start(QString *error) override {
        const QString address = m_sim.start(m_simArgs, error);
        if (address.isEmpty())
            return false;
        m_startMs = QDateTime::currentMSecsSinceEpoch();
        if (m_kind == Kind::Agent) {
            m_agent.configure(address, m_brokerPort, {{QStringLiteral("client_id"), m_label}});
            return m_agent.start(error);
        }
        QStringList args{QStringLiteral("--tcp"), address, QStringLiteral("monitor"),
                         QStringLiteral("--journal"), journalPath()};
        if (m_kind == Kind::CliSlow)
            args << QStringLiteral("--interval") << QStringLiteral("5000");
        m_cli.setStandardOutputFile(QProcess::nullDevice());
        m_cli.setStandardErrorFile(m_dir.filePath(QStringLiteral("cli.err")));
        m_cli.start(testing::binaryPath(QStringLiteral("tipscope-cli")), args);
        if (!m_cli.waitForStarted(5000)) {
            *error = QStringLiteral("tipscope-cli did not start: ") + m_cli.errorString();
            return false;
        }
        return true;
    }

    void stop() override {
        m_endMs = QDateTime::currentMSecsSinceEpoch();
        if (m_kind == Kind::Agent) {
            (void)m_agent.stop();
        } else {
            ::kill(pid_t(m_cli.processId()), SIGINT); // as Ctrl-C: joints in progress are kept
            if (!m_cli.waitForFinished(20000))
                m_cli.kill();
        }
    }

    QList<JointFigure> figures() override {
        JointTruth truth;
        truth.parseLog(m_sim.errorText());
        QList<JointRecord> found;
        journal::JournalReader reader;
        if (const auto opened = reader.open(journalPath()); !opened) {
            printError(QStringLiteral("%1: %2").arg(m_label, opened.error()));
        } else if (const auto joints = reader.joints({}); !joints) {
            printError(QStringLiteral("%1: %2").arg(m_label, joints.error()));
        } else {
            for (const journal::StoredJoint &j : joints.value())
                found.append(j.record);
        }
        return scoreJoints(truth, found, m_startMs + kWarmUpMs, m_endMs, m_label);
    }

private:
    [[nodiscard]] QString journalPath() const {
        return m_kind == Kind::Agent ? m_agent.journalPath()
                                     : m_dir.filePath(QStringLiteral("journal.sqlite"));
    }

    Kind m_kind;
    int m_brokerPort;
    QString m_label;
    DetachedSim m_sim;
    QStringList m_simArgs;
    QTemporaryDir m_dir;
    QProcess m_cli;
    testing::AgentProcess m_agent;
    qint64 m_startMs = 0;
    qint64 m_endMs = 0;
};

std::optional<Options> parse(const QStringList &args) {
    Options o;
    const std::optional<double> minutes = numberOption(args, "--minutes", o.minutes, 0.1, 24 * 60);
    const std::optional<double> perMinute = numberOption(args, "--per-minute", o.perMinute, 1, 60);
    const std::optional<qint64> seed = wholeOption(args, "--seed", o.seed, 0, UINT32_MAX);
    if (!minutes || !perMinute || !seed)
        return std::nullopt;
    o.minutes = *minutes;
    o.perMinute = *perMinute;
    o.seed = quint32(*seed);
    if (const qsizetype i = args.indexOf(QStringLiteral("--sets")); i >= 0)
        o.sets = args.value(i + 1).split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (const qsizetype i = args.indexOf(QStringLiteral("--frontends")); i >= 0)
        o.frontEnds = args.value(i + 1).split(QLatin1Char(','), Qt::SkipEmptyParts);
    return o;
}

std::unique_ptr<Run> makeRun(const Options &o, const sim::JointShapeSet &shapes,
                             const QString &frontEnd, int brokerPort, const QString &label) {
    if (frontEnd == QLatin1String("core"))
        return std::make_unique<CoreRun>(o, shapes, true, label);
    if (frontEnd == QLatin1String("core_fixed"))
        return std::make_unique<CoreRun>(o, shapes, false, label);
    if (frontEnd == QLatin1String("cli"))
        return std::make_unique<ProcessRun>(o, shapes, ProcessRun::Kind::Cli, brokerPort, label);
    if (frontEnd == QLatin1String("cli_5000"))
        return std::make_unique<ProcessRun>(o, shapes, ProcessRun::Kind::CliSlow, brokerPort,
                                            label);
    return std::make_unique<ProcessRun>(o, shapes, ProcessRun::Kind::Agent, brokerPort, label);
}

} // namespace

int runJointWireBench(const QStringList &args) {
    const std::optional<Options> parsed = parse(args);
    if (!parsed)
        return 2;
    const Options &o = *parsed;
    for (const QString &set : o.sets)
        if (!sim::JointShapeSet::named(set)) {
            printError(QStringLiteral("--sets takes %1, not %2")
                           .arg(sim::JointShapeSet::names().join(QLatin1Char(',')), set));
            return 2;
        }
    for (const QString &f : o.frontEnds)
        if (!kFrontEnds.contains(f)) {
            printError(QStringLiteral("--frontends takes %1, not %2")
                           .arg(kFrontEnds.join(QLatin1Char(',')), f));
            return 2;
        }
    printText(QStringLiteral("joints.wire.station"), QStringLiteral("DME, 4 ports"));
    printFigure(QStringLiteral("joints.wire.baud"), kBaud, QStringLiteral("baud"), 0);
    printFigure(QStringLiteral("joints.wire.minutes"), o.minutes, QStringLiteral("min"), 1);
    printFigure(QStringLiteral("joints.wire.per_minute"), o.perMinute,
                QStringLiteral("joints/min/port"), 1);

    // The programs keep their settings, limits and work context in a home of this run's own.
    QTemporaryDir home;
    qputenv("HOME", home.path().toLocal8Bit());
    qputenv("XDG_CONFIG_HOME", (home.path() + QStringLiteral("/config")).toLocal8Bit());
    qputenv("XDG_DATA_HOME", (home.path() + QStringLiteral("/data")).toLocal8Bit());
    stopOnSignals();

    std::unique_ptr<testing::MosquittoBroker> broker;
    if (o.frontEnds.contains(QStringLiteral("agent"))) {
        QString error;
        broker = std::make_unique<testing::MosquittoBroker>();
        if (const QString whyNot = testing::MosquittoBroker::skipReason(); !whyNot.isEmpty()) {
            printError(QStringLiteral("the agent needs a broker: ") + whyNot);
            return 1;
        }
        if (!broker->start(&error)) {
            printError(error);
            return 1;
        }
    }

    struct Entry {
        QString name;
        std::unique_ptr<Run> run;
    };
    std::vector<Entry> runs;
    for (const QString &set : o.sets)
        for (const QString &frontEnd : o.frontEnds) {
            const QString name = set + QLatin1Char('.') + frontEnd;
            runs.push_back({name, makeRun(o, *sim::JointShapeSet::named(set), frontEnd,
                                          broker ? broker->port() : 0, name)});
        }
    for (Entry &e : runs) {
        QString error;
        if (!e.run->start(&error)) {
            printError(QStringLiteral("%1: %2").arg(e.name, error));
            return 1;
        }
    }
    (void)runUntil([] { return false; }, int(o.minutes * 60'000));
    for (Entry &e : runs)
        e.run->stop();
    for (Entry &e : runs)
        for (const JointFigure &f : e.run->figures())
            printFigure(QStringLiteral("joints.%1.%2").arg(e.name, f.name), f.value, f.unit,
                        f.decimals);
    return interrupted() ? 1 : 0;
}

} // namespace tipscope::bench
