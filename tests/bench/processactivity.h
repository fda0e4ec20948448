// ProcessActivity: where a process's time goes besides computing, counted over a measuring
// window so that a benchmark can print it per transaction and the next cut can be seen without
// a profiler: the system calls its threads made and the times they went to sleep and were woken
// (voluntary context switches: a wait in poll() that ended, a lock that was taken).
//
// The system calls are counted by the kernel's raw_syscalls:sys_enter tracepoint, one counter
// per thread that exists when the window opens (a thread started later is not counted). Opening
// it needs the right to trace the process (root, CAP_PERFMON, or perf_event_paranoid <= 1); where
// that is refused, syscalls() says so and the rest is still measured.
#pragma once

#include <QString>
#include <QStringList>
#include <QtGlobal>
#include <optional>
#include <vector>

namespace tipscope::bench {

class ProcessActivity {
public:
    // Opens the counters of `pid`'s threads (of its thread `onlyThread` alone when given) and
    // takes the first reading.
    explicit ProcessActivity(qint64 pid, qint64 onlyThread = 0);
    ~ProcessActivity();
    ProcessActivity(const ProcessActivity &) = delete;
    ProcessActivity &operator=(const ProcessActivity &) = delete;

    // Since construction: the system calls made (nullopt when they could not be counted, with
    // the reason in whyNoSyscalls()), and the voluntary context switches of the threads.
    [[nodiscard]] std::optional<qint64> syscalls() const;
    [[nodiscard]] const QString &whyNoSyscalls() const { return m_whyNot; }
    [[nodiscard]] qint64 wakeUps() const;

private:
    [[nodiscard]] qint64 voluntarySwitches() const;

    qint64 m_pid = 0;
    QStringList m_threads;       // empty: every thread of the process, as it is at each reading
    std::vector<int> m_counters; // perf event descriptors, one per thread
    QString m_whyNot;
    qint64 m_wakeUpsBefore = 0;
};

} // namespace tipscope::bench
