// `tipscope-bench journal`, sustained inserts: the main thread's 10 ms timer appends, the
// journal's writer commits; how many records a second reach the disk, and how late the timer
// runs meanwhile compared with the same timer alone.
#include "benchsupport.h"
#include "journalbenchphases.h"

#include "journal/journal.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <functional>

namespace tipscope::bench {

namespace {

constexpr int kTickMs = 10;
constexpr int kMaxPerTick = 2000; // up to 200,000 records a second offered
constexpr int kKeepPending = 6000;
constexpr qint64 kT0 = 1'700'000'000'000;

// Runs a 10 ms timer for `seconds` and calls `work` on each tick; how late each tick came (ms).
QList<double> runTicks(int seconds, const std::function<void()> &work) {
    QEventLoop loop;
    QTimer timer;
    timer.setTimerType(Qt::PreciseTimer);
    timer.setInterval(kTickMs);
    QElapsedTimer clock;
    qint64 last = 0;
    QList<double> lateness;
    QObject::connect(&timer, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        lateness.append(qMax(0.0, double(now - last) / 1e6 - kTickMs));
        last = now;
        if (now >= qint64(seconds) * 1'000'000'000)
            loop.quit();
        else if (work)
            work();
    });
    clock.start();
    timer.start();
    loop.exec();
    return lateness;
}

void printStalls(const QString &prefix, const QList<double> &lateness) {
    printFigure(prefix + QStringLiteral("_max_ms"), quantile(lateness, 1.0), QStringLiteral("ms"),
                2);
    printFigure(prefix + QStringLiteral("_p99_ms"), quantile(lateness, 0.99), QStringLiteral("ms"),
                2);
}

using Append = std::function<QUuid(journal::Journal &, qint64)>;

// Appends with `append` from the timer for `seconds`, at most `perTick` records a tick and never
// more than the journal holds; prints the committed records a second (when `rateFigure`), the
// main thread's cost per append and the timer's lateness as `<prefix>_poll_stall_*`.
bool sustained(const QString &prefix, const QString &path, int seconds, int perTick,
               bool rateFigure, const Append &append) {
    journal::JournalOptions options;
    options.retentionDays = 0;
    journal::Journal journal(path, options);
    if (!waitJournalOpened(journal))
        return false;
    qint64 committed = 0;
    QObject::connect(&journal, &journal::Journal::committed, [&](const journal::Committed &ids) {
        committed += ids.joints.size() + ids.events.size();
    });
    qint64 next = 0;
    qint64 appendNs = 0;
    const QList<double> lateness = runTicks(seconds, [&] {
        const qint64 room = qMin<qint64>(perTick, kKeepPending - journal.pendingCount());
        QElapsedTimer cost;
        cost.start();
        for (qint64 i = 0; i < room; ++i)
            append(journal, next++);
        appendNs += cost.nsecsElapsed();
    });
    if (rateFigure) {
        printFigure(prefix + QStringLiteral("_inserts_per_s"), double(committed) / seconds,
                    QStringLiteral("records/s"), 0);
        printFigure(prefix + QStringLiteral("_append_us"),
                    double(appendNs) / 1e3 / double(qMax<qint64>(1, next)), QStringLiteral("us"),
                    2);
    }
    printStalls(prefix + (rateFigure ? QStringLiteral("_saturated_poll_stall")
                                     : QStringLiteral("_poll_stall")),
                lateness);
    if (journal.lostCount() > 0)
        printNote(QStringLiteral("%1 records lost: %2")
                      .arg(journal.lostCount())
                      .arg(journal.lossReason()));
    return true;
}

// Saturated: as many as the writer takes (the stall then includes the appends themselves);
// paced: 10 a tick, 1000 records a second, far above a plant's joints and events.
bool sustainedPair(const QString &name, const QString &folder, int seconds, const Append &append) {
    const QString prefix = QStringLiteral("journal.") + name;
    return sustained(prefix, QDir(folder).filePath(name + QStringLiteral("-saturated.sqlite")),
                     seconds, kMaxPerTick, true, append) &&
           sustained(prefix + QStringLiteral("_paced_1000_per_s"),
                     QDir(folder).filePath(name + QStringLiteral("-paced.sqlite")), seconds, 10,
                     false, append);
}

} // namespace

model::JointRecord benchJoint(qint64 i, qint64 startMs) {
    model::JointRecord j;
    j.device = {QStringLiteral("/dev/serial/by-id/usb-JBC_%1-if00").arg(i % 10), 1,
                QStringLiteral("DDE-2C"), QStringLiteral("9876543")};
    j.port = int(i / 10 % 4) + 1;
    j.tool = QStringLiteral("C245");
    j.startMs = startMs;
    j.endMs = j.startMs + 1800;
    j.setpoint = 350;
    j.lowestTip = 320 - int(i % 20);
    j.dipDepth = j.setpoint - j.lowestTip;
    j.recoveryMs = 600 + i % 400;
    j.durationMs = 1800;
    j.powerPeak = 70 + int(i % 30);
    j.powerIntegral = 80.5 + double(i % 100) / 4;
    // Mostly good joints, as on a working line.
    const int v = int(i % 100);
    j.verdict = v < 90   ? model::JointVerdict::Ok
                : v < 95 ? model::JointVerdict::SlowRecovery
                : v < 98 ? model::JointVerdict::TooDeep
                         : model::JointVerdict::Incomplete;
    return j;
}

journal::JournalEvent benchEvent(qint64 i, qint64 timeMs) {
    journal::JournalEvent e;
    e.kind = journal::JournalEvent::Kind::Write;
    e.device = benchJoint(i, timeMs).device;
    e.port = int(i / 10 % 4) + 1;
    e.timeMs = timeMs;
    e.text = QStringLiteral("ST%1 = 350 °C").arg(*e.port);
    e.details = {{QStringLiteral("code"), QStringLiteral("ST%1").arg(*e.port)},
                 {QStringLiteral("value"), QStringLiteral("00350")},
                 {QStringLiteral("read_back"), QStringLiteral("match")}};
    return e;
}

bool waitJournalOpened(journal::Journal &journal) {
    QElapsedTimer clock;
    clock.start();
    while (journal.state() == journal::JournalState::Opening && clock.elapsed() < 30'000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    if (journal.state() == journal::JournalState::Ready)
        return true;
    printError(QStringLiteral("journal did not open: %1").arg(journal.errorText()));
    return false;
}

bool journalSustainedPhase(const JournalBenchOptions &o, const QString &folder) {
    printStalls(QStringLiteral("journal.idle_poll_stall"), runTicks(o.seconds, {}));
    return sustainedPair(QStringLiteral("joint"), folder, o.seconds,
                         [](journal::Journal &j, qint64 i) {
                             return j.append(benchJoint(i, kT0 + i * 1000));
                         }) &&
           sustainedPair(QStringLiteral("event"), folder, o.seconds,
                         [](journal::Journal &j, qint64 i) {
                             return j.append(benchEvent(i, kT0 + i * 1000));
                         });
}

} // namespace tipscope::bench
