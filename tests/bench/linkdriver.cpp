#include "linkdriver.h"

#include "benchsupport.h"

#include <QEventLoop>
#include <QTimer>

namespace tipscope::bench {

using namespace tipscope::link;

namespace {

constexpr int kOpenTimeoutMs = 5000;
constexpr int kFirstAnswerTimeoutMs = 3000;

void account(TrafficCounts &c, const Reply &reply) {
    if (reply.ok()) {
        ++c.ok;
        c.requestBytes += reply.request().encode().size();
        c.answerBytes += reply.answer().encode().size();
        return;
    }
    ++c.failed;
    if (c.firstError.isEmpty())
        c.firstError = reply.request().toString() + QStringLiteral(": ") + reply.errorString();
}

} // namespace

SimLink::~SimLink() {
    m_line.reset(); // fails what is still pending while the simulator still runs
    m_sim.stop();
}

bool SimLink::start(const QStringList &simArgs, int turnaroundMs, QString *error) {
    m_path = m_sim.start(simArgs, error);
    if (m_path.isEmpty())
        return false;
    LineSettings settings;
    settings.kind = LineSettings::Kind::Serial;
    settings.serial.portName = m_path;
    settings.queue.turnaroundMs = turnaroundMs;
    m_line = std::make_unique<Line>(Line::makeTransport(settings, nullptr), settings);
    QEventLoop loop;
    QObject::connect(m_line.get(), &Line::stateChanged, &loop, [&loop](Line::State s) {
        if (s != Line::State::Opening)
            loop.quit();
    });
    QTimer::singleShot(kOpenTimeoutMs, &loop, &QEventLoop::quit);
    m_line->open();
    if (m_line->state() == Line::State::Opening)
        loop.exec();
    if (m_line->state() != Line::State::Open) {
        *error = QStringLiteral("cannot open %1: %2").arg(m_path, m_line->stateText());
        return false;
    }
    return true;
}

std::optional<qint64> SimLink::simCpuUs() {
    return processCpuUs(m_sim.process().processId());
}

ReadLoop::ReadLoop(RequestQueue &queue, QObject *parent)
    : QObject(parent)
    , m_queue(queue) {}

void ReadLoop::addChain(const QList<Request> &requests) {
    m_chains.append({requests, 0});
}

void ReadLoop::start() {
    m_running = true;
    for (int i = 0; i < m_chains.size(); ++i)
        send(i);
}

void ReadLoop::send(int chain) {
    Chain &c = m_chains[chain];
    const Request &request = c.requests[c.next];
    c.next = (c.next + 1) % int(c.requests.size());
    Reply *reply = m_queue.enqueue(request, this);
    connect(reply, &Reply::finished, this, [this, reply, chain] {
        reply->deleteLater();
        if (!m_running)
            return;
        account(m_counts, *reply);
        if (reply->ok() && !m_answered) {
            m_answered = true;
            Q_EMIT firstAnswer();
        }
        send(chain);
    });
}

WriteProbe::WriteProbe(RequestQueue &queue, Request first, Request second, int intervalMs,
                       QObject *parent)
    : QObject(parent)
    , m_queue(queue)
    , m_requests{std::move(first), std::move(second)} {
    m_clock.start();
    m_timer.setInterval(intervalMs);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &WriteProbe::send);
}

void WriteProbe::send() {
    const Request &request = m_requests[m_next];
    m_next = (m_next + 1) % int(m_requests.size());
    const qint64 enqueuedNs = m_clock.nsecsElapsed();
    Reply *reply = m_queue.enqueue(request, this);
    connect(reply, &Reply::finished, this, [this, reply, enqueuedNs] {
        reply->deleteLater();
        if (!m_timer.isActive())
            return; // stopped: the line is being torn down
        account(m_counts, *reply);
        if (reply->ok())
            m_latenciesMs.append(double(m_clock.nsecsElapsed() - enqueuedNs) / 1e6);
        Q_EMIT finishedWrite(int(m_counts.ok + m_counts.failed));
    });
}

void runEventLoopFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, Qt::PreciseTimer, &loop, &QEventLoop::quit);
    loop.exec();
}

std::optional<Window> measure(SimLink &link, ReadLoop &loop, int seconds, const char *phase) {
    QEventLoop wait;
    QObject::connect(&loop, &ReadLoop::firstAnswer, &wait, &QEventLoop::quit);
    QTimer::singleShot(kFirstAnswerTimeoutMs, &wait, &QEventLoop::quit);
    loop.start();
    wait.exec();
    if (loop.counts().ok == 0) {
        printError(QStringLiteral("%1 phase: no answer from tipscope-sim on %2 (%3)")
                       .arg(QLatin1String(phase), link.path(), loop.counts().firstError));
        loop.stop();
        return std::nullopt;
    }
    runEventLoopFor(kWarmupMs);
    loop.resetCounts();
    const qint64 cpu0 = selfCpuUs();
    const std::optional<qint64> sim0 = link.simCpuUs();
    QElapsedTimer clock;
    clock.start();
    runEventLoopFor(seconds * 1000);
    Window w;
    w.counts = loop.counts();
    w.seconds = double(clock.nsecsElapsed()) / 1e9;
    w.cpuUs = selfCpuUs() - cpu0;
    const std::optional<qint64> sim1 = link.simCpuUs();
    if (sim0 && sim1)
        w.simCpuUs = *sim1 - *sim0;
    loop.stop();
    if (w.counts.failed > 0)
        printNote(QStringLiteral("%1 phase: %2 request(s) failed, first: %3")
                      .arg(QLatin1String(phase))
                      .arg(w.counts.failed)
                      .arg(w.counts.firstError));
    if (w.counts.ok == 0) {
        printError(QStringLiteral("%1 phase: the answers stopped").arg(QLatin1String(phase)));
        return std::nullopt;
    }
    return w;
}

void runUntilEnoughWrites(WriteProbe &probe, int minWrites, int seconds, int limitMs) {
    QEventLoop wait;
    QElapsedTimer clock;
    clock.start();
    QObject::connect(&probe, &WriteProbe::finishedWrite, &wait, [&] {
        if (probe.latenciesMs().size() >= minWrites && clock.elapsed() >= seconds * 1000)
            wait.quit();
    });
    QTimer::singleShot(qMax(seconds * 1000, limitMs), &wait, &QEventLoop::quit);
    probe.start();
    wait.exec();
    probe.stop();
}

} // namespace tipscope::bench
