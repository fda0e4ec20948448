#include "cfxbench.h"

#include "agentprocess.h"
#include "benchsupport.h"
#include "cfxtap.h"
#include "mosquittobroker.h"
#include "rabbitmqbroker.h"
#include "simstations.h"

#include "journal/journalreader.h"
#include "journal/workcontextfile.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QTimer>
#include <memory>
#include <optional>
#include <vector>

namespace tipscope::bench {

namespace {

constexpr int kConnectTimeoutMs = 120000;
// The tips heating up and the first reading of everything stay out of the figures.
constexpr int kWarmupMs = 15000;
constexpr int kDrainTimeoutMs = 180000;
// Into a board change's burst: the agent has journaled the change and is sending its messages.
constexpr int kKillAfterMs = 300;
// A queue of its own: what is sent while the consumer reconnects waits there for it.
const QString kQueue = QStringLiteral("/queue/tipscope-cfx-bench");

const QString kWorkStarted = QStringLiteral("CFX.Production.WorkStarted");
const QString kWorkCompleted = QStringLiteral("CFX.Production.WorkCompleted");
const QString kUnitsProcessed = QStringLiteral("CFX.Production.Processing.UnitsProcessed");

struct Options {
    int stations = 32;
    int seconds = 120;
    int outageS = 60;
    int boardS = 10;
    int jointsPerMinute = 2;
    int pace = kPaceBaud;
};

// Everything the bench starts, destroyed in reverse: the agent stops first (saying goodbye while
// the broker still runs), then the stations, the consumer and the broker.
struct Plant {
    std::unique_ptr<testing::MosquittoBroker> mqtt;
    std::unique_ptr<testing::RabbitMqBroker> broker;
    CfxTap tap;
    std::vector<SimStation> stations;
    std::unique_ptr<testing::AgentProcess> agent;
    QStringList handles; // the endpoints that said EndpointConnected
};

// Names a new board in the agent's work context every few seconds, as a line's board change
// does; the boards named are kept in order.
class BoardChanger {
public:
    explicit BoardChanger(int everyS) {
        m_timer.setInterval(everyS * 1000);
        QObject::connect(&m_timer, &QTimer::timeout, [this] { next(); });
    }
    void startOn(const QString &journalPath) {
        m_contextPath = journal::workContextPathFor(journalPath);
        next();
        m_timer.start();
    }
    void stop() { m_timer.stop(); }
    // The next board, now.
    void next() {
        model::WorkContext context;
        context.boardSerial =
            QStringLiteral("BENCH-%1").arg(m_boards.size() + 1, 5, 10, QLatin1Char('0'));
        if (journal::writeWorkContext(m_contextPath, context))
            m_boards.append(context.boardSerial);
        else
            printError(QStringLiteral("cannot write the work context ") + m_contextPath);
    }
    // No board: the last one ends.
    void end() {
        m_timer.stop();
        if (!journal::writeWorkContext(m_contextPath, model::WorkContext()))
            printError(QStringLiteral("cannot write the work context ") + m_contextPath);
    }
    [[nodiscard]] const QStringList &boards() const { return m_boards; }

private:
    QTimer m_timer;
    QString m_contextPath;
    QStringList m_boards;
};

qint64 nowMs() {
    return QDateTime::currentMSecsSinceEpoch();
}

int parseOptions(const QStringList &args, Options *o) {
    const QStringList known{QStringLiteral("--stations"),          QStringLiteral("--seconds"),
                            QStringLiteral("--outage-s"),          QStringLiteral("--board-s"),
                            QStringLiteral("--joints-per-minute"), QStringLiteral("--pace")};
    for (int i = 0; i < args.size(); ++i) {
        if (args.at(i) == QLatin1String("--help") || args.at(i) == QLatin1String("-h")) {
            printNote(QStringLiteral("tipscope-bench cfx [--stations N] [--seconds S] "
                                     "[--outage-s O] [--board-s B] [--joints-per-minute J] "
                                     "[--pace BAUD]"));
            return 0;
        }
        if (!known.contains(args.at(i))) {
            printError(QStringLiteral("unknown option %1 (--help lists them)").arg(args.at(i)));
            return 2;
        }
        ++i; // its value, checked below
    }
    const auto read = [&](const char *name, int *value, int least, int most) {
        const std::optional<qint64> v = wholeOption(args, name, *value, least, most);
        if (v)
            *value = int(*v);
        return v.has_value();
    };
    const bool ok =
        read("--stations", &o->stations, 1, 256) && read("--seconds", &o->seconds, 10, 86400) &&
        read("--outage-s", &o->outageS, 1, 3600) && read("--board-s", &o->boardS, 1, 3600) &&
        read("--joints-per-minute", &o->jointsPerMinute, 1, 60) &&
        read("--pace", &o->pace, 0, 1000000);
    return ok ? -1 : 2;
}

QJsonArray linesOf(const Plant &plant) {
    QJsonArray lines;
    for (const SimStation &s : plant.stations)
        lines.append(testing::AgentProcess::tcpLineJson(s.sim->name(), s.address));
    return lines;
}

// An agent on every station publishing MQTT, as a plant runs it; CFX beside it when `cfx`.
std::unique_ptr<testing::AgentProcess> makeAgent(const Plant &plant, bool cfx) {
    auto agent = std::make_unique<testing::AgentProcess>();
    QJsonObject extra{{QStringLiteral("site"), QStringLiteral("bench")}};
    if (cfx)
        extra.insert(QStringLiteral("cfx"),
                     QJsonObject{{QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                                 {QStringLiteral("port"), plant.broker->port()},
                                 {QStringLiteral("address"), kQueue},
                                 {QStringLiteral("retry_max_s"), 1}});
    agent->configureLines(linesOf(plant), plant.mqtt->port(),
                          {{QStringLiteral("client_id"), cfx ? QStringLiteral("cfx-bench-on")
                                                             : QStringLiteral("cfx-bench-off")}},
                          extra);
    return agent;
}

void printAgentLog(testing::AgentProcess &agent) {
    printNote(QStringLiteral("the agent's last words:\n") + lastLines(agent.log(), 40));
}

bool startStations(Plant &plant, const Options &o) {
    plant.stations = startSimStations(
        o.stations, [&](int i) { return plantStationArgs(i, o.jointsPerMinute, o.pace, 0); });
    return !plant.stations.empty();
}

qint64 stationsCpuUs(const Plant &plant) {
    qint64 us = 0;
    for (const SimStation &s : plant.stations)
        us += processCpuUs(s.sim->pid()).value_or(0);
    return us;
}

double percentOfOneCore(qint64 us, qint64 wallMs) {
    return wallMs > 0 ? 100.0 * double(us) / (double(wallMs) * 1000) : 0;
}

// The agent without CFX, on the same stations and boards: its CPU over the window.
std::optional<double> measureWithoutCfx(Plant &plant, const Options &o) {
    auto agent = makeAgent(plant, false);
    QString error;
    if (!agent->start(&error)) {
        printError(error);
        return std::nullopt;
    }
    BoardChanger boards(o.boardS);
    boards.startOn(agent->journalPath());
    (void)runUntil([] { return false; }, kWarmupMs);
    if (agent->process().state() != QProcess::Running) {
        printError(QStringLiteral("the agent without CFX ended"));
        printAgentLog(*agent);
        return std::nullopt;
    }
    const qint64 before = processCpuUs(agent->process().processId()).value_or(0);
    QElapsedTimer wall;
    wall.start();
    (void)runUntil([] { return false; }, o.seconds * 1000);
    const qint64 used = processCpuUs(agent->process().processId()).value_or(0) - before;
    if (agent->process().state() != QProcess::Running) {
        printError(QStringLiteral("the agent without CFX ended during the run"));
        printAgentLog(*agent);
        return std::nullopt;
    }
    (void)agent->stop();
    return percentOfOneCore(used, wall.elapsed());
}

bool startAgentWithCfx(Plant &plant, const Options &o) {
    plant.agent = makeAgent(plant, true);
    QString error;
    const qint64 since = nowMs();
    if (!plant.agent->start(&error)) {
        printError(error);
        return false;
    }
    const int devices = o.stations + o.stations / 2; // every other line has a feeder
    if (!runUntil([&] { return plant.tap.connectedSince(since) >= devices; }, kConnectTimeoutMs)) {
        printError(QStringLiteral("%1 of %2 endpoints said EndpointConnected")
                       .arg(plant.tap.connectedSince(since))
                       .arg(devices));
        printAgentLog(*plant.agent);
        return false;
    }
    // The soldering stations: a feeder makes no joints and works on no board. Its handle names
    // its model, SFR, second (vendor.model.unit, docs/cfx.md).
    QSet<QString> handles;
    for (const TappedMessage &m : plant.tap.messages())
        if (m.name == QLatin1String("CFX.EndpointConnected") &&
            !m.source.section(QLatin1Char('.'), 1, 1).startsWith(QLatin1String("SFR")))
            handles.insert(m.source);
    plant.handles = handles.values();
    printFigure(QStringLiteral("cfx.connect_s"), double(nowMs() - since) / 1000,
                QStringLiteral("s"));
    return true;
}

// Every station said WorkStarted for `board`.
bool startedEverywhere(const Plant &plant, const QString &board) {
    return plant.tap.startedAt(board).size() >= plant.handles.size();
}

// A board's UnitsProcessed can leave only once its last joint is over: the board latency above
// counts from the board's end, and so holds the wait for a joint still under way then (up to its
// recovery) and the readings its measure needs after it (at most 1.5 s). Counted instead from
// when the board's last joint was back within its band (or the board's end, if later), it is what
// the journal, the forwarder, the broker and the consumer add.
void printLatencyAfterLastJoint(const Plant &plant, qint64 fromMs, qint64 untilMs) {
    journal::JournalReader reader;
    if (const auto opened = reader.open(plant.agent->journalPath()); !opened) {
        printNote(QStringLiteral("cfx.board_latency_after_last_joint: ") + opened.error());
        return;
    }
    journal::JointFilter filter;
    filter.sinceMs = fromMs - 120'000; // a board's joints began before its end, within reason
    const auto joints = reader.joints(filter);
    if (!joints) {
        printNote(QStringLiteral("cfx.board_latency_after_last_joint: ") + joints.error());
        return;
    }
    QHash<QString, qint64> endOf;
    for (const journal::StoredJoint &j : *joints)
        endOf.insert(j.uid.toString(QUuid::WithoutBraces), j.record.endMs);
    QList<double> latencies;
    for (const TappedMessage &m : plant.tap.messages()) {
        if (m.name != kUnitsProcessed || m.arrivedMs < fromMs || m.arrivedMs >= untilMs ||
            m.stampMs == 0)
            continue;
        qint64 ready = m.stampMs;
        for (const QString &id : m.jointIds)
            ready = qMax(ready, endOf.value(id, 0));
        latencies.append(double(m.arrivedMs - ready));
    }
    printFigure(QStringLiteral("cfx.board_latency_after_last_joint_p50_ms"),
                quantile(latencies, 0.5), QStringLiteral("ms"));
    printFigure(QStringLiteral("cfx.board_latency_after_last_joint_p99_ms"),
                quantile(latencies, 0.99), QStringLiteral("ms"));
}

void measureWithCfx(Plant &plant, const Options &o, double cpuOffPct) {
    (void)runUntil([] { return false; }, kWarmupMs);
    const qint64 pid = plant.agent->process().processId();
    const qint64 agentBefore = processCpuUs(pid).value_or(0);
    const qint64 stationsBefore = stationsCpuUs(plant);
    const qint64 consumerBefore = processCpuUs(plant.tap.pid()).value_or(0);
    const qint64 fromMs = nowMs();
    (void)runUntil([] { return false; }, o.seconds * 1000);
    const qint64 untilMs = nowMs();
    const qint64 wallMs = untilMs - fromMs;
    const double cpuOnPct = percentOfOneCore(processCpuUs(pid).value_or(0) - agentBefore, wallMs);
    const QString core = QStringLiteral("% of one core");
    printFigure(QStringLiteral("cfx.seconds"), double(wallMs) / 1000, QStringLiteral("s"));
    printFigure(QStringLiteral("cfx.agent_cpu_off_pct"), cpuOffPct, core, 2);
    printFigure(QStringLiteral("cfx.agent_cpu_on_pct"), cpuOnPct, core, 2);
    printFigure(QStringLiteral("cfx.agent_cpu_ratio"), cpuOffPct > 0 ? cpuOnPct / cpuOffPct : 0,
                QStringLiteral("x"), 2);
    printFigure(QStringLiteral("cfx.stations_cpu_pct"),
                percentOfOneCore(stationsCpuUs(plant) - stationsBefore, wallMs), core);
    printFigure(
        QStringLiteral("cfx.consumer_cpu_pct"),
        percentOfOneCore(processCpuUs(plant.tap.pid()).value_or(0) - consumerBefore, wallMs), core);
    QList<double> all;
    QList<double> boardEnds;
    for (const TappedMessage &m : plant.tap.messages()) {
        if (m.arrivedMs < fromMs || m.arrivedMs >= untilMs || m.stampMs == 0)
            continue;
        all.append(double(m.arrivedMs - m.stampMs));
        if (m.name == kUnitsProcessed)
            boardEnds.append(double(m.arrivedMs - m.stampMs));
    }
    printFigure(QStringLiteral("cfx.latency_p50_ms"), quantile(all, 0.5), QStringLiteral("ms"));
    printFigure(QStringLiteral("cfx.latency_p99_ms"), quantile(all, 0.99), QStringLiteral("ms"));
    printFigure(QStringLiteral("cfx.board_latency_p50_ms"), quantile(boardEnds, 0.5),
                QStringLiteral("ms"));
    printFigure(QStringLiteral("cfx.board_latency_p99_ms"), quantile(boardEnds, 0.99),
                QStringLiteral("ms"));
    printLatencyAfterLastJoint(plant, fromMs, untilMs);
    printFigure(QStringLiteral("cfx.messages_per_s"), double(all.size()) * 1000 / double(wallMs),
                QStringLiteral("msg/s"));
}

// Stops the broker while boards keep changing, starts it again and times the backlog's drain.
bool measureOutage(Plant &plant, const BoardChanger &boards, const Options &o) {
    QString error;
    const qint64 outageMs = nowMs();
    if (!plant.broker->pause(&error)) {
        printError(error);
        return false;
    }
    (void)runUntil([] { return false; }, o.outageS * 1000);
    if (!plant.broker->resume(&error)) {
        printError(QStringLiteral("the broker did not start again: ") + error);
        return false;
    }
    const qint64 returnMs = nowMs();
    // Messages leave in order per endpoint: once every station said WorkStarted for the last
    // board named in the outage, all it sent before has arrived.
    const QString last = boards.boards().constLast();
    if (!runUntil([&] { return startedEverywhere(plant, last); }, kDrainTimeoutMs)) {
        printError(QStringLiteral("%1 of %2 stations said WorkStarted for %3 after the outage")
                       .arg(plant.tap.startedAt(last).size())
                       .arg(plant.handles.size())
                       .arg(last));
        printAgentLog(*plant.agent);
        return false;
    }
    qint64 count = 0;
    qint64 first = 0;
    qint64 lastArrival = 0;
    for (const TappedMessage &m : plant.tap.messages()) {
        if (m.arrivedMs < returnMs || m.stampMs < outageMs || m.stampMs >= returnMs)
            continue;
        ++count;
        first = first == 0 ? m.arrivedMs : std::min(first, m.arrivedMs);
        lastArrival = std::max(lastArrival, m.arrivedMs);
    }
    const double drainS = double(lastArrival - first) / 1000;
    printFigure(QStringLiteral("cfx.outage_s"), double(returnMs - outageMs) / 1000,
                QStringLiteral("s"));
    printFigure(QStringLiteral("cfx.backlog_messages"), double(count), QStringLiteral("messages"),
                0);
    printFigure(QStringLiteral("cfx.backlog_first_s"),
                count > 0 ? double(first - returnMs) / 1000 : 0, QStringLiteral("s"), 2);
    printFigure(QStringLiteral("cfx.backlog_drain_s"), drainS, QStringLiteral("s"), 2);
    printFigure(QStringLiteral("cfx.backlog_drain_per_s"), drainS > 0 ? double(count) / drainS : 0,
                QStringLiteral("messages/s"));
    return true;
}

// Kills the agent in a board change's burst and starts it again on its journal.
bool killAndRestart(Plant &plant, BoardChanger &boards) {
    boards.stop();
    boards.next();
    waitMs(kKillAfterMs);
    const qint64 killMs = nowMs();
    plant.agent->kill();
    QString error;
    if (!plant.agent->start(&error)) {
        printError(error);
        return false;
    }
    const QString last = boards.boards().constLast();
    if (!runUntil(
            [&] {
                return startedEverywhere(plant, last) &&
                       plant.tap.connectedSince(killMs) >= plant.handles.size();
            },
            kDrainTimeoutMs)) {
        printError(QStringLiteral("after the SIGKILL, %1 of %2 stations said WorkStarted for %3")
                       .arg(plant.tap.startedAt(last).size())
                       .arg(plant.handles.size())
                       .arg(last));
        printAgentLog(*plant.agent);
        return false;
    }
    printFigure(QStringLiteral("cfx.restart_s"), double(nowMs() - killMs) / 1000,
                QStringLiteral("s"));
    return true;
}

// Ends the last board, waits for its WorkCompleted everywhere and stops the agent.
bool finish(Plant &plant, BoardChanger &boards) {
    boards.next(); // one more board after the restart, sent by the new agent alone
    waitMs(2000);
    boards.end();
    const QString last = boards.boards().constLast();
    const auto completedEverywhere = [&] {
        QString transaction;
        for (const TappedMessage &m : plant.tap.messages())
            if (m.name == kWorkStarted && m.board == last)
                transaction = m.transaction;
        QSet<QString> at;
        for (const TappedMessage &m : plant.tap.messages())
            if (m.name == kWorkCompleted && m.transaction == transaction)
                at.insert(m.source);
        return !transaction.isEmpty() && at.size() >= plant.handles.size();
    };
    if (!runUntil(completedEverywhere, kDrainTimeoutMs)) {
        printError(QStringLiteral("the last board, %1, was not completed everywhere").arg(last));
        printAgentLog(*plant.agent);
        return false;
    }
    (void)plant.agent->stop();
    waitMs(2000); // the goodbyes
    plant.tap.read();
    return true;
}

// Every board named, at every station, against what arrived and what the journal holds.
void countLostAndDuplicated(const Plant &plant, const BoardChanger &boards) {
    const QList<TappedMessage> &messages = plant.tap.messages();
    QHash<QString, int> copies;               // UniqueID -> times received
    QHash<QString, QSet<QString>> idsOfOne;   // name|source|transaction -> UniqueIDs
    QHash<QString, QSet<QString>> idsOfJoint; // JointId -> UnitsProcessed UniqueIDs
    QHash<QString, QSet<QString>> started;    // board -> stations
    QHash<QString, QString> transactionOf;    // board -> transaction
    QHash<QString, QSet<QString>> completed;  // transaction -> stations
    for (const TappedMessage &m : messages) {
        ++copies[m.uniqueId];
        if (!m.transaction.isEmpty())
            idsOfOne[m.name + QLatin1Char('|') + m.source + QLatin1Char('|') + m.transaction]
                .insert(m.uniqueId);
        for (const QString &joint : m.jointIds)
            idsOfJoint[joint].insert(m.uniqueId);
        if (m.name == kWorkStarted) {
            started[m.board].insert(m.source);
            transactionOf.insert(m.board, m.transaction);
        } else if (m.name == kWorkCompleted) {
            completed[m.transaction].insert(m.source);
        }
    }
    qint64 sameId = 0;
    for (const int n : std::as_const(copies))
        sameId += n - 1;
    qint64 twoIds = 0;
    for (const QSet<QString> &ids : std::as_const(idsOfOne))
        twoIds += ids.size() - 1;
    for (const QSet<QString> &ids : std::as_const(idsOfJoint))
        twoIds += ids.size() - 1;
    qint64 lost = 0;
    for (const QString &board : boards.boards()) {
        const QSet<QString> &at = started[board];
        const QSet<QString> &done = completed[transactionOf.value(board)];
        qint64 missing = 0;
        QStringList notStarted;
        QStringList notCompleted;
        for (const QString &handle : plant.handles) {
            if (!at.contains(handle))
                notStarted.append(handle);
            if (!done.contains(handle))
                notCompleted.append(handle);
        }
        missing = notStarted.size() + notCompleted.size();
        if (missing > 0)
            printNote(QStringLiteral("board %1: no WorkStarted from %2; no WorkCompleted from %3")
                          .arg(board, notStarted.join(QLatin1Char(' ')),
                               notCompleted.join(QLatin1Char(' '))));
        lost += missing;
    }
    qint64 joints = 0;
    qint64 jointsLost = 0;
    journal::JournalReader reader;
    if (const auto opened = reader.open(plant.agent->journalPath()); !opened) {
        printError(QStringLiteral("the agent's journal: ") + opened.error());
    } else {
        for (const QString &board : boards.boards()) {
            journal::JointFilter filter;
            filter.boardSerial = board;
            const auto made = reader.joints(filter);
            if (!made) {
                printError(made.error());
                continue;
            }
            qint64 missing = 0;
            for (const journal::StoredJoint &joint : *made) {
                ++joints;
                if (!idsOfJoint.contains(joint.uid.toString(QUuid::WithoutBraces)))
                    ++missing;
            }
            if (missing > 0)
                printNote(QStringLiteral("board %1: %2 of its %3 joints in no UnitsProcessed")
                              .arg(board)
                              .arg(missing)
                              .arg(made->size()));
            jointsLost += missing;
        }
    }
    printFigure(QStringLiteral("cfx.messages_total"), double(messages.size()),
                QStringLiteral("messages"), 0);
    printFigure(QStringLiteral("cfx.boards"), double(boards.boards().size()),
                QStringLiteral("boards"), 0);
    printFigure(QStringLiteral("cfx.joints_total"), double(joints), QStringLiteral("joints"), 0);
    printFigure(QStringLiteral("cfx.messages_lost"), double(lost), QStringLiteral("messages"), 0);
    printFigure(QStringLiteral("cfx.joints_lost"), double(jointsLost), QStringLiteral("joints"), 0);
    printFigure(QStringLiteral("cfx.duplicates_same_id"), double(sameId),
                QStringLiteral("messages"), 0);
    printFigure(QStringLiteral("cfx.duplicates_two_ids"), double(twoIds),
                QStringLiteral("messages"), 0);
    printFigure(QStringLiteral("cfx.consumer_complaints"), double(plant.tap.complaints().size()),
                QStringLiteral("messages"), 0);
    for (const QString &complaint : plant.tap.complaints().mid(0, 5))
        printNote(complaint);
}

} // namespace

int runCfxBench(const QStringList &args) {
    Options o;
    if (const int status = parseOptions(args, &o); status >= 0)
        return status;
    for (const QString &whyNot : {testing::MosquittoBroker::skipReason(),
                                  testing::RabbitMqBroker::skipReason(), CfxTap::skipReason()})
        if (!whyNot.isEmpty()) {
            printError(whyNot);
            return 1;
        }
    stopOnSignals();
    Plant plant;
    plant.mqtt = std::make_unique<testing::MosquittoBroker>();
    plant.broker = std::make_unique<testing::RabbitMqBroker>();
    QString error;
    if (!plant.mqtt->start(&error) || !plant.broker->start(&error)) {
        printError(error);
        return 1;
    }
    if (!startStations(plant, o))
        return 1;
    const std::optional<double> cpuOff = measureWithoutCfx(plant, o);
    if (!cpuOff || interrupted())
        return 1;
    if (!plant.tap.start(plant.broker->url(), kQueue, &error)) {
        printError(error);
        return 1;
    }
    if (!startAgentWithCfx(plant, o))
        return 1;
    BoardChanger boards(o.boardS);
    boards.startOn(plant.agent->journalPath());
    measureWithCfx(plant, o, *cpuOff);
    if (interrupted() || !measureOutage(plant, boards, o) || interrupted() ||
        !killAndRestart(plant, boards) || !finish(plant, boards))
        return 1;
    countLostAndDuplicated(plant, boards);
    return interrupted() ? 1 : 0;
}

} // namespace tipscope::bench
