// Simulated stations for the benches that run a fleet (`tipscope-bench fleet`, `plant`): each a
// tipscope-sim started detached and serving TCP on a free loopback port, its address read from
// the file its standard output goes to.
//
// Detached, a simulator leaves no pipe or process handle in the bench, whose event loop would
// otherwise poll three of them a station beside what is measured. Its standard input is a FIFO the
// bench writes commands into without polling it (stats()). A DetachedSim sends its simulator
// SIGTERM when destroyed, so a bench that fails half-way leaves none running.
#pragma once

#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace tipscope::bench {

class DetachedSim {
public:
    explicit DetachedSim(QString name)
        : m_name(std::move(name)) {}
    ~DetachedSim();
    DetachedSim(const DetachedSim &) = delete;
    DetachedSim &operator=(const DetachedSim &) = delete;

    // Starts the simulator and returns the address it serves, or empty with `error` set.
    [[nodiscard]] QString start(const QStringList &args, QString *error);
    [[nodiscard]] const QString &name() const { return m_name; }
    [[nodiscard]] qint64 pid() const { return m_pid; }
    // What the simulator wrote on standard error so far (the joints it made, among others).
    [[nodiscard]] QString errorText() const;
    // The requests the simulator has answered so far (its `stats` command), nullopt when it did
    // not say within a second.
    [[nodiscard]] std::optional<qint64> answers();

private:
    QString m_name;
    QTemporaryDir m_dir;
    qint64 m_pid = 0;
    int m_control = -1; // the write end of the simulator's standard input
};

// One started station: its simulator and the address to connect to.
struct SimStation {
    std::unique_ptr<DetachedSim> sim;
    QString address; // host:port
};

// Starts `stations` simulators named line01, line02, ..., the i-th (from 0) with argsOf(i).
// Empty, with the failure printed, when one did not start (those started are stopped).
[[nodiscard]] std::vector<SimStation>
startSimStations(int stations, const std::function<QStringList(int)> &argsOf);

// The plant benches' station `i` (from 0): a DME on TCP making `jointsPerMinute` random joints
// on every port (seeded by i), paced like a `pace` baud wire and handing its answers over every
// `chunkMs` (0: a byte at a time), with an SFR feeder on every other line.
[[nodiscard]] QStringList plantStationArgs(int i, int jointsPerMinute, int pace, int chunkMs);

// The requests all `stations` have answered so far; nullopt when one did not say.
[[nodiscard]] std::optional<qint64> answersOf(const std::vector<SimStation> &stations);

// Of an agent's log, the last `count` lines, for a failure note.
[[nodiscard]] QString lastLines(const QString &log, int count);

} // namespace tipscope::bench
