// The soak's control of tipscope-sim: its standard input as an asynchronous command channel,
// and the faults the simulator has no share option for.
//
// SimConsole writes commands to the simulator's standard input and hands each reply line to the
// handler given with it, in order; nothing blocks the client's event loop. A batch goes out in
// one write, so the simulator runs it back to back with no wire traffic in between (this is how
// a window's request count is taken exactly).
//
// FaultWindows injects the two faults tipscope-sim offers only as line-wide switches, through
// commands that leave its fault generator alone (every command that goes through
// SimLine::setFaults(), "latency" included, reseeds it, which would make the drop and corruption
// pattern repeat after each window):
//  - NAKs: "robot-mode off" makes the station answer NAK 00005 to everything, so a 20 ms window
//    of robot mode off NAKs exactly the requests that arrive in it;
//  - answers delayed past the client's timeout: "pace 300" for 200 ms stalls the wire. The
//    answer on the wire at that moment resumes only when the window closes, well after the
//    answer budget (about 125 ms at 19200 baud); a request that arrives during the window is
//    received at 300 baud, so its answer is late too. Each window counts as one delayed answer
//    plus the requests that arrived in it.
// Every second it compares what was injected with its target share of the requests so far and
// opens a window when it is behind. Request counts are exact: requests seen by the simulator
// between the "stats" before and after the window.
#pragma once

#include <QMap>
#include <QObject>
#include <QProcess>
#include <QTimer>
#include <deque>
#include <functional>
#include <optional>

namespace tipscope::bench {

struct SimStats {
    qint64 requests = 0, writes = 0, answers = 0, dropped = 0, corrupted = 0, garbled = 0,
           badRequests = 0, lostRequests = 0, garbledRequests = 0;
    // Parses the reply of the "stats" command.
    [[nodiscard]] static std::optional<SimStats> parse(const QString &line);
};

// Parses the reply of the "get" command ("ST1=350 A11=0"); nullopt for an error.
[[nodiscard]] std::optional<QMap<QByteArray, qint64>> parseSettings(const QString &reply);

class SimConsole : public QObject {
    Q_OBJECT
public:
    using Handler = std::function<void(const QString &reply)>;

    explicit SimConsole(QProcess &process, QObject *parent = nullptr);
    void send(const QStringList &commands, const QList<Handler> &handlers = {});
    void send(const QString &command, Handler handler = {}) {
        send(QStringList{command}, QList<Handler>{std::move(handler)});
    }
    [[nodiscard]] int waiting() const { return int(m_waiting.size()); }

private:
    void onReadyRead();

    QProcess &m_process;
    std::deque<Handler> m_waiting;
};

class FaultWindows : public QObject {
    Q_OBJECT
public:
    FaultWindows(SimConsole &console, double nakShare, double delayShare, int normalBaud,
                 QObject *parent = nullptr);
    void start() { m_tick.start(); }
    void stop() { m_tick.stop(); }
    void setPaused(bool paused) { m_paused = paused; }
    [[nodiscard]] bool windowOpen() const { return m_windowOpen; }

    [[nodiscard]] qint64 naked() const { return m_injected[Nak]; }
    [[nodiscard]] qint64 delayed() const { return m_injected[Delay]; }
    [[nodiscard]] int nakWindows() const { return m_windows[Nak]; }
    [[nodiscard]] int delayWindows() const { return m_windows[Delay]; }

private:
    enum Kind { Nak = 0, Delay = 1 };
    void tick();
    void open(Kind kind);

    SimConsole &m_console;
    double m_share[2];
    int m_normalBaud;
    QTimer m_tick;
    bool m_windowOpen = false;
    bool m_paused = false;
    qint64 m_requests = 0;
    qint64 m_injected[2] = {0, 0};
    int m_windows[2] = {0, 0};
    int m_next = Nak;
};

} // namespace tipscope::bench
