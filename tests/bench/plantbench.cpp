#include "plantbench.h"

#include "agentprocess.h"
#include "benchsupport.h"
#include "mosquittobroker.h"
#include "plantsubscriber.h"
#include "processactivity.h"
#include "simstations.h"
#include "wirefloor.h"

#include "journal/journalreader.h"

#include <QCommandLineParser>
#include <QDateTime>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QTextStream>
#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace tipscope::bench {

namespace {

constexpr int kOnlineTimeoutMs = 120000;
// The tips heating up and the first reading of everything stay out of the figures.
constexpr int kWarmupMs = 10000;
constexpr int kFloorSeconds = 30;
// A joint that started during the outage is journaled once its recovery ended (at most 3 s with
// the simulator's random joints) and the journal made it durable: wait this long after the
// broker's return before the backlog read from the journal is taken as complete.
constexpr int kJournalSettleMs = 10000;
constexpr int kForwardTimeoutMs = 120000;

struct Options {
    int stations = 32;
    int seconds = 120;
    int outageS = 60;
    int jointsPerMinute = 2;
    int intervalMs = 1000;
    int pace = 19200;
    int chunkMs = 0;
    int load = 0;
};

// Everything the bench starts, destroyed in reverse: the agent stops first (publishing offline
// while the broker still runs), then the stations, the subscriber and the broker.
struct Plant {
    std::unique_ptr<testing::MosquittoBroker> broker;
    PlantSubscriber subscriber;
    std::vector<SimStation> stations;
    testing::AgentProcess agent;
    int devices = 0;
    std::optional<WireFloor> floor;
};

qint64 nowMs() {
    return QDateTime::currentMSecsSinceEpoch();
}

// Returns -1 to go on, or the exit status to end with.
int parseOptions(const QStringList &args, Options *o) {
    QCommandLineParser p;
    const auto number = [](const char *name, const char *help) {
        return QCommandLineOption(QString::fromLatin1(name), QString::fromLatin1(help),
                                  QStringLiteral("N"));
    };
    p.addOptions(
        {number("stations", "Simulated stations, one line each (default 32)."),
         number("seconds", "The measuring window in seconds (default 120)."),
         number("outage-s", "How long the broker is stopped, in seconds (default 60)."),
         number("joints-per-minute", "Joints a minute on every port (default 2)."),
         number("interval-ms", "The agent's live interval in ms (default 1000)."),
         number("pace", "The stations' wire in baud, 0 for unpaced (default 19200)."),
         number("chunk-ms", "The stations hand their answers over every N ms, as a USB adapter "
                            "does (default 0: a byte at a time)."),
         number("load", "Busy loops beside the whole run, floor included (default 0)."),
         {{QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Show this help.")}});
    if (!p.parse(QStringList{QStringLiteral("tipscope-bench plant")} + args)) {
        printError(p.errorText());
        return 2;
    }
    if (p.isSet(QStringLiteral("help"))) {
        QTextStream(stdout) << p.helpText();
        return 0;
    }
    const auto read = [&](const char *name, int *value, int least) {
        if (!p.isSet(QString::fromLatin1(name)))
            return true;
        bool ok = false;
        *value = p.value(QString::fromLatin1(name)).toInt(&ok);
        if (ok && *value >= least)
            return true;
        printError(QStringLiteral("--%1 takes a whole number from %2").arg(name).arg(least));
        return false;
    };
    const bool ok = read("stations", &o->stations, 1) && read("seconds", &o->seconds, 1) &&
                    read("outage-s", &o->outageS, 1) &&
                    read("joints-per-minute", &o->jointsPerMinute, 1) &&
                    read("interval-ms", &o->intervalMs, 100) && read("pace", &o->pace, 0) &&
                    read("chunk-ms", &o->chunkMs, 0) && read("load", &o->load, 0);
    return ok ? -1 : 2;
}

void printAgentLog(testing::AgentProcess &agent) {
    printNote(QStringLiteral("the agent's last words:\n") + lastLines(agent.log(), 20));
}

// Starts the broker, the subscriber, the stations and the agent, and waits until every device
// says online. False, with the reason printed, when something did not come up.
bool startPlant(Plant &plant, const Options &o) {
    plant.stations = startSimStations(o.stations, [&](int i) {
        return plantStationArgs(i, o.jointsPerMinute, o.pace, o.chunkMs);
    });
    if (plant.stations.empty())
        return false;
    // Before the broker and the agent: the floor's loop holds this process's event loop, and
    // the agent would take the simulators over.
    QString error;
    plant.floor = measureWireFloor(plant.stations, kFloorSeconds * 1000, &error);
    if (!plant.floor) {
        printError(error);
        return false;
    }
    printFigure(QStringLiteral("plant.floor_tx_per_s"), plant.floor->txPerS,
                QStringLiteral("tx/s"));
    printFigure(QStringLiteral("plant.floor_cpu_us_per_tx"), plant.floor->cpuUsPerTx,
                QStringLiteral("us"));
    printFigure(QStringLiteral("plant.floor_cpu_pct"),
                plant.floor->cpuPercentAt(plant.floor->txPerS), QStringLiteral("% of one core"));
    testing::BrokerOptions brokerOptions;
    brokerOptions.persistence = true;
    plant.broker = std::make_unique<testing::MosquittoBroker>(brokerOptions);
    if (!plant.broker->start(&error) || !plant.subscriber.connectTo(plant.broker->port(), &error)) {
        printError(error);
        return false;
    }
    QJsonArray lines;
    for (const SimStation &s : plant.stations)
        lines.append(testing::AgentProcess::tcpLineJson(s.sim->name(), s.address));
    plant.devices = o.stations + o.stations / 2;
    plant.agent.configureLines(
        lines, plant.broker->port(),
        {{QStringLiteral("client_id"), QStringLiteral("plant-bench-agent")}},
        {{QStringLiteral("site"), QStringLiteral("bench")},
         {QStringLiteral("live"), QJsonObject{{QStringLiteral("interval_ms"), o.intervalMs}}}});
    if (!plant.agent.start(&error)) {
        printError(error);
        return false;
    }
    QElapsedTimer connecting;
    connecting.start();
    if (!runUntil([&] { return plant.subscriber.onlineDevices() >= plant.devices; },
                  kOnlineTimeoutMs)) {
        printError(QStringLiteral("%1 of %2 devices came online")
                       .arg(plant.subscriber.onlineDevices())
                       .arg(plant.devices));
        printAgentLog(plant.agent);
        return false;
    }
    printFigure(QStringLiteral("plant.devices"), plant.devices, QStringLiteral("devices"), 0);
    printFigure(QStringLiteral("plant.connect_s"), double(connecting.elapsed()) / 1000,
                QStringLiteral("s"));
    return true;
}

// The agent's CPU time, the stations' together and this process's, in microseconds.
struct CpuTimes {
    qint64 agentUs = 0;
    qint64 stationsUs = 0;
    qint64 selfUs = 0;
};

CpuTimes cpuTimes(Plant &plant) {
    CpuTimes t;
    t.agentUs = processCpuUs(plant.agent.process().processId()).value_or(0);
    for (const SimStation &s : plant.stations)
        t.stationsUs += processCpuUs(s.sim->pid()).value_or(0);
    t.selfUs = selfCpuUs();
    return t;
}

// The agent's cost per transaction beside the floor's: CPU, system calls and wake-ups.
void printAgentCost(const Plant &plant, double cpuUs, double transactions,
                    const ProcessActivity &activity) {
    if (transactions <= 0) {
        printNote(QStringLiteral("plant.cpu_over_floor: no transactions counted"));
        return;
    }
    printFigure(QStringLiteral("plant.agent_cpu_us_per_tx"), cpuUs / transactions,
                QStringLiteral("us"));
    printFigure(QStringLiteral("plant.cpu_over_floor"),
                cpuUs / transactions / plant.floor->cpuUsPerTx, QString(), 2);
    if (const std::optional<qint64> syscalls = activity.syscalls())
        printFigure(QStringLiteral("plant.syscalls_per_tx"), double(*syscalls) / transactions,
                    QString(), 2);
    else
        printNote(QStringLiteral("plant.syscalls_per_tx: not measured, %1")
                      .arg(activity.whyNoSyscalls()));
    if (plant.floor->syscallsPerTx)
        printFigure(QStringLiteral("plant.floor_syscalls_per_tx"), *plant.floor->syscallsPerTx,
                    QString(), 2);
    printFigure(QStringLiteral("plant.wakeups_per_tx"), double(activity.wakeUps()) / transactions,
                QString(), 2);
    printFigure(QStringLiteral("plant.floor_wakeups_per_tx"), plant.floor->wakeUpsPerTx, QString(),
                2);
}

void measureLive(Plant &plant, int seconds) {
    const std::optional<qint64> answersBefore = answersOf(plant.stations);
    const ProcessActivity activity(plant.agent.process().processId());
    const CpuTimes before = cpuTimes(plant);
    plant.subscriber.startMeasuring();
    QElapsedTimer wall;
    wall.start();
    (void)runUntil([] { return false; }, seconds * 1000);
    const CpuTimes after = cpuTimes(plant);
    const std::optional<qint64> answersAfter = answersOf(plant.stations);
    const double s = double(wall.elapsed()) / 1000;
    const auto percent = [s](qint64 us) { return 100.0 * double(us) / (s * 1e6); };
    const QList<double> &latencies = plant.subscriber.liveLatenciesMs();
    printFigure(QStringLiteral("plant.seconds"), s, QStringLiteral("s"));
    const QString core = QStringLiteral("% of one core");
    printFigure(QStringLiteral("plant.agent_cpu_pct"), percent(after.agentUs - before.agentUs),
                core);
    if (answersBefore && answersAfter) {
        const double transactions = double(*answersAfter - *answersBefore);
        printFigure(QStringLiteral("plant.agent_tx_per_s"), transactions / s,
                    QStringLiteral("tx/s"));
        printAgentCost(plant, double(after.agentUs - before.agentUs), transactions, activity);
    } else {
        printNote(QStringLiteral("plant.cpu_over_floor: a station did not say how many requests "
                                 "it answered"));
    }
    // For context: both share the machine with the agent.
    printFigure(QStringLiteral("plant.stations_cpu_pct"),
                percent(after.stationsUs - before.stationsUs), core);
    printFigure(QStringLiteral("plant.subscriber_cpu_pct"), percent(after.selfUs - before.selfUs),
                core);
    printFigure(QStringLiteral("plant.live_latency_p50_ms"), quantile(latencies, 0.5),
                QStringLiteral("ms"));
    printFigure(QStringLiteral("plant.live_latency_p99_ms"), quantile(latencies, 0.99),
                QStringLiteral("ms"));
    printFigure(QStringLiteral("plant.messages_per_s"),
                double(plant.subscriber.measuredMessages()) / s, QStringLiteral("msg/s"));
    printFigure(QStringLiteral("plant.ports"), plant.subscriber.ports(), QStringLiteral("ports"),
                0);
    printFigure(QStringLiteral("plant.live_per_port_hz"),
                double(plant.subscriber.measuredLive()) / qMax(1, plant.subscriber.ports()) / s,
                QStringLiteral("Hz"), 2);
}

// The ids of the journal's joints that started in [sinceMs, untilMs) (all with nullopt).
QList<QString> journalJointIds(const journal::JournalReader &reader, std::optional<qint64> sinceMs,
                               std::optional<qint64> untilMs) {
    journal::JointFilter filter;
    filter.sinceMs = sinceMs;
    filter.untilMs = untilMs;
    filter.order = journal::Order::OldestFirst;
    QList<QString> ids;
    const auto joints = reader.joints(filter);
    if (joints)
        for (const journal::StoredJoint &j : joints.value())
            ids.append(j.uid.toString(QUuid::WithoutBraces));
    return ids;
}

qsizetype missingOf(const QList<QString> &ids, const PlantSubscriber &subscriber) {
    return std::count_if(ids.cbegin(), ids.cend(), [&](const QString &id) {
        return !subscriber.jointArrivals().contains(id);
    });
}

// Stops the broker for the outage, starts it again and waits for the backlog. Returns when the
// broker came back (ms since the epoch), nullopt when it did not.
std::optional<qint64> measureOutage(Plant &plant, int outageS) {
    journal::JournalReader reader;
    if (const auto opened = reader.open(plant.agent.journalPath()); !opened) {
        printError(QStringLiteral("the agent's journal: ") + opened.error());
        return std::nullopt;
    }
    const qint64 outageStartMs = nowMs();
    plant.broker->stop();
    (void)runUntil([] { return false; }, outageS * 1000);
    QString error;
    if (!plant.broker->start(&error)) {
        printError(QStringLiteral("the broker did not start again: ") + error);
        return std::nullopt;
    }
    const qint64 returnMs = nowMs();
    QList<QString> backlog;
    const bool drained = runUntil(
        [&] {
            backlog = journalJointIds(reader, outageStartMs, returnMs);
            return nowMs() - returnMs >= kJournalSettleMs &&
                   missingOf(backlog, plant.subscriber) == 0;
        },
        kForwardTimeoutMs);
    qint64 firstArrivalMs = std::numeric_limits<qint64>::max();
    qint64 lastArrivalMs = returnMs;
    for (const QString &id : backlog)
        if (const auto arrivals = plant.subscriber.jointArrivals().value(id); !arrivals.isEmpty()) {
            firstArrivalMs = std::min(firstArrivalMs, arrivals.first());
            lastArrivalMs = std::max(lastArrivalMs, arrivals.first());
        }
    const double drainS = double(lastArrivalMs - returnMs) / 1000;
    printFigure(QStringLiteral("plant.outage_s"), double(returnMs - outageStartMs) / 1000,
                QStringLiteral("s"));
    printFigure(QStringLiteral("plant.backlog_joints"), double(backlog.size()),
                QStringLiteral("joints"), 0);
    if (!drained)
        printError(QStringLiteral("%1 of the backlog's joints had not arrived after %2 s")
                       .arg(missingOf(backlog, plant.subscriber))
                       .arg(kForwardTimeoutMs / 1000));
    // How much of the drain is the agent's reconnecting (its retries back off up to 1 s).
    printFigure(QStringLiteral("plant.backlog_first_s"),
                backlog.isEmpty() || firstArrivalMs > lastArrivalMs
                    ? 0
                    : double(firstArrivalMs - returnMs) / 1000,
                QStringLiteral("s"), 2);
    printFigure(QStringLiteral("plant.backlog_drain_s"), drainS, QStringLiteral("s"), 2);
    printFigure(QStringLiteral("plant.backlog_drain_per_s"),
                drainS > 0 ? double(backlog.size()) / drainS : 0, QStringLiteral("joints/s"));
    return returnMs;
}

// Every joint the journal holds now, once the agent had the time to forward them all. Each
// duplicate is noted with its copies' arrivals from the broker's return, to tell the agent's
// resending from the broker's redelivery to the subscriber.
void countLost(Plant &plant, qint64 returnMs) {
    journal::JournalReader reader;
    QList<QString> all;
    if (reader.open(plant.agent.journalPath()))
        all = journalJointIds(reader, std::nullopt, std::nullopt);
    (void)runUntil([&] { return missingOf(all, plant.subscriber) == 0; }, kForwardTimeoutMs);
    qint64 duplicates = 0;
    const auto &received = plant.subscriber.jointArrivals();
    for (auto it = received.cbegin(); it != received.cend(); ++it) {
        duplicates += it.value().size() - 1;
        if (it.value().size() < 2)
            continue;
        QStringList atS;
        for (const qint64 ms : it.value())
            atS.append(QString::number(double(ms - returnMs) / 1000, 'f', 3));
        printNote(QStringLiteral("joint %1 arrived %2 times, at %3 s from the broker's return")
                      .arg(it.key())
                      .arg(it.value().size())
                      .arg(atS.join(QStringLiteral(", "))));
    }
    printFigure(QStringLiteral("plant.joints_total"), double(all.size()), QStringLiteral("joints"),
                0);
    printFigure(QStringLiteral("plant.joints_lost"), double(missingOf(all, plant.subscriber)),
                QStringLiteral("joints"), 0);
    printFigure(QStringLiteral("plant.joints_duplicated"), double(duplicates),
                QStringLiteral("joints"), 0);
}

} // namespace

int runPlantBench(const QStringList &args) {
    Options options;
    if (const int status = parseOptions(args, &options); status >= 0)
        return status;
    if (const QString whyNot = testing::MosquittoBroker::skipReason(); !whyNot.isEmpty()) {
        printError(whyNot);
        return 1;
    }
    stopOnSignals();
    // The subscriber's retries during the outage would bury the figures; connectTo() says why it
    // could not connect.
    QLoggingCategory::setFilterRules(QStringLiteral("tipscope.mqtt=false"));
    const BusyLoad load(options.load);
    printFigure(QStringLiteral("plant.load_processes"), load.count(), QStringLiteral("loops"), 0);
    Plant plant;
    if (!startPlant(plant, options))
        return 1;
    (void)runUntil([] { return false; }, kWarmupMs);
    if (!interrupted())
        measureLive(plant, options.seconds);
    const std::optional<qint64> returnMs =
        interrupted() ? std::nullopt : measureOutage(plant, options.outageS);
    if (!returnMs)
        return 1;
    countLost(plant, *returnMs);
    if (plant.agent.process().state() != QProcess::Running) {
        printError(QStringLiteral("the agent ended during the run"));
        printAgentLog(plant.agent);
        return 1;
    }
    return interrupted() ? 1 : 0;
}

} // namespace tipscope::bench
