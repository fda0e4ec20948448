// The moving parts of the link benchmark, all driven by the Qt event loop.
//
// SimLink starts tipscope-sim on a PTY and opens a link::Line (SerialTransport, the default
// queue settings apart from the turnaround) on the path the simulator prints. ReadLoop keeps
// chains of reads in flight: each chain has one request outstanding and enqueues its next one
// from the finished() of the previous, so the queue is never starved by the benchmark itself.
// WriteProbe enqueues a user write at a fixed interval and records the time from enqueue() to
// Reply::finished. Replies are parented to the driver that asked and deleted once read. The
// free functions run the event loop for a phase: nothing in them blocks the client.
#pragma once

#include "link/line.h"
#include "ptyfixtures.h"

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QTimer>
#include <memory>

namespace tipscope::bench {

class SimLink {
public:
    SimLink() = default;
    ~SimLink();
    SimLink(const SimLink &) = delete;
    SimLink &operator=(const SimLink &) = delete;

    // Starts the simulator with `simArgs` and opens the line; false with *error on failure.
    [[nodiscard]] bool start(const QStringList &simArgs, int turnaroundMs, QString *error);
    [[nodiscard]] link::RequestQueue &queue() { return m_line->queue(); }
    [[nodiscard]] QString path() const { return m_path; }
    // CPU time the simulator has used so far, in microseconds, when /proc allows reading it.
    [[nodiscard]] std::optional<qint64> simCpuUs();

private:
    testing::SimProcess m_sim;
    std::unique_ptr<link::Line> m_line;
    QString m_path;
};

// What a driver has seen since its counters were last reset.
struct TrafficCounts {
    qint64 ok = 0;
    qint64 failed = 0;
    qint64 requestBytes = 0; // encoded request frames of the answered requests
    qint64 answerBytes = 0;  // encoded answer frames
    QString firstError;
};

class ReadLoop : public QObject {
    Q_OBJECT
public:
    explicit ReadLoop(link::RequestQueue &queue, QObject *parent = nullptr);

    // A chain cycles through `requests`, one outstanding at a time.
    void addChain(const QList<link::Request> &requests);
    void start();
    void stop() { m_running = false; }
    void resetCounts() { m_counts = {}; }
    [[nodiscard]] const TrafficCounts &counts() const { return m_counts; }

Q_SIGNALS:
    void firstAnswer();

private:
    struct Chain {
        QList<link::Request> requests;
        int next = 0;
    };
    void send(int chain);

    link::RequestQueue &m_queue;
    QList<Chain> m_chains;
    TrafficCounts m_counts;
    bool m_running = false;
    bool m_answered = false;
};

class WriteProbe : public QObject {
    Q_OBJECT
public:
    WriteProbe(link::RequestQueue &queue, link::Request first, link::Request second, int intervalMs,
               QObject *parent = nullptr);

    void start() { m_timer.start(); }
    void stop() { m_timer.stop(); }
    [[nodiscard]] const QList<double> &latenciesMs() const { return m_latenciesMs; }
    [[nodiscard]] const TrafficCounts &counts() const { return m_counts; }

Q_SIGNALS:
    void finishedWrite(int count);

private:
    void send();

    link::RequestQueue &m_queue;
    QList<link::Request> m_requests;
    int m_next = 0;
    QTimer m_timer;
    QElapsedTimer m_clock;
    QList<double> m_latenciesMs;
    TrafficCounts m_counts;
};

// Time given to a fresh line before measuring, so opening and the first frames are not counted.
inline constexpr int kWarmupMs = 300;

// One measured window of a ReadLoop.
struct Window {
    double seconds = 0;
    TrafficCounts counts;
    qint64 cpuUs = 0;               // this process, user + system
    std::optional<qint64> simCpuUs; // the simulator, when /proc allows reading it
};

void runEventLoopFor(int ms);

// Starts `loop`, waits for its first answer and a warm-up, then measures for `seconds`. Reports
// a failure on standard error (prefixed with `phase`) and returns nullopt when nothing answers.
[[nodiscard]] std::optional<Window> measure(SimLink &link, ReadLoop &loop, int seconds,
                                            const char *phase);

// Runs `probe` until `minWrites` writes have succeeded and `seconds` have passed, or `limitMs`.
void runUntilEnoughWrites(WriteProbe &probe, int minWrites, int seconds, int limitMs);

} // namespace tipscope::bench
