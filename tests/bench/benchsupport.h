// Shared pieces of tipscope-bench: how a figure is printed, the machine context every run starts
// with, and CPU-time readings.
//
// Every figure is one line on standard output, "name: value unit" (for example
// "link.paced_tx_per_s: 70.4 tx/s"), so a script can grep and compare runs. Errors and notes go
// to standard error and never mix with the figures.
#pragma once

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>
#include <vector>

namespace tipscope::bench {

void printFigure(const QString &name, double value, const QString &unit, int decimals = 1);
void printText(const QString &name, const QString &value);
void printError(const QString &message);
void printNote(const QString &message);

// bench.cores, bench.cpu, bench.build, bench.qt, bench.kernel.
void printMachineContext();

// User plus system CPU time of this process so far, in microseconds (getrusage).
[[nodiscard]] qint64 selfCpuUs();
// User plus system CPU time of another process from /proc/<pid>/stat; nullopt if unreadable.
[[nodiscard]] std::optional<qint64> processCpuUs(qint64 pid);

// The value after `--name` in a subcommand's arguments, or `fallback`.
[[nodiscard]] QString optionValue(const QStringList &args, const char *name,
                                  const QString &fallback);

// The number after `--name`, or `fallback` when the option is not given. A value that is
// missing, not a finite number, or outside [min, max] is refused: nullopt, after one error line
// naming the option and its range. Nothing is clamped: a figure measured with another value
// than the one asked for would be read as that one's.
[[nodiscard]] std::optional<double> numberOption(const QStringList &args, const char *name,
                                                 double fallback, double min, double max);
// The same for a whole number.
[[nodiscard]] std::optional<qint64> wholeOption(const QStringList &args, const char *name,
                                                qint64 fallback, qint64 min, qint64 max);

// A field of /proc/self/status in bytes ("VmRSS:", "VmHWM:"); -1 when unreadable.
[[nodiscard]] qint64 selfStatusBytes(const char *field);
// Runs the event loop for `ms`.
void waitMs(int ms);
// Runs the event loop (no polling, unlike QTest::qWait) until `done` holds, checked every 100 ms,
// or `timeoutMs` passed, or SIGINT or SIGTERM came after stopOnSignals(); returns done().
[[nodiscard]] bool runUntil(const std::function<bool()> &done, int timeoutMs);
// From now on SIGINT and SIGTERM end every runUntil() and make interrupted() true, so a bench
// that starts processes can still stop them all on its way out.
void stopOnSignals();
[[nodiscard]] bool interrupted();

// `count` busy loops (`sh -c 'while :; do :; done'`) beside a benchmark, so that its figures,
// the floor's and ours alike, can be read on a machine with other work (`--load N`). Killed
// when destroyed; a loop whose bench died first ends by itself within a round.
class BusyLoad {
public:
    explicit BusyLoad(int count);
    ~BusyLoad();
    BusyLoad(const BusyLoad &) = delete;
    BusyLoad &operator=(const BusyLoad &) = delete;
    [[nodiscard]] int count() const { return int(m_pids.size()); }

private:
    std::vector<qint64> m_pids;
};

// The benches' simulated wires are paced like a 19200-baud line, 8N1: ten bits a byte.
inline constexpr int kPaceBaud = 19200;
inline constexpr double kWireBytesPerSecond = kPaceBaud / 10.0;
// What such a wire carries, in transactions a second, at the frame sizes a line used: `answered`
// transactions took `bytes` sent and received. 0 when nothing was answered.
[[nodiscard]] double pacedWireLimitTxPerS(qint64 answered, qint64 bytes);

// The p-quantile (0..1) of `values` by the nearest rank; 0 for an empty list.
[[nodiscard]] double quantile(QList<double> values, double p);

} // namespace tipscope::bench
