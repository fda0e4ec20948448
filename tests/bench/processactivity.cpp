#include "processactivity.h"

#include <QDir>
#include <QFile>
#include <cerrno>
#include <cstring>
#include <linux/perf_event.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace tipscope::bench {

namespace {

// The tracepoint's id, from tracefs (mounted at either place).
std::optional<quint64> syscallTracepointId() {
    for (const char *path : {"/sys/kernel/tracing/events/raw_syscalls/sys_enter/id",
                             "/sys/kernel/debug/tracing/events/raw_syscalls/sys_enter/id"}) {
        QFile file(QString::fromLatin1(path));
        bool ok = false;
        const quint64 id =
            file.open(QIODevice::ReadOnly) ? file.readAll().trimmed().toULongLong(&ok) : 0;
        if (ok)
            return id;
    }
    return std::nullopt;
}

QStringList threadsOf(qint64 pid) {
    return QDir(QStringLiteral("/proc/%1/task").arg(pid))
        .entryList(QDir::Dirs | QDir::NoDotAndDotDot);
}

} // namespace

qint64 ProcessActivity::voluntarySwitches() const {
    qint64 sum = 0;
    for (const QString &tid : m_threads.isEmpty() ? threadsOf(m_pid) : m_threads) {
        QFile file(QStringLiteral("/proc/%1/task/%2/status").arg(m_pid).arg(tid));
        if (!file.open(QIODevice::ReadOnly))
            continue;
        for (const QByteArray &line : file.readAll().split('\n'))
            if (line.startsWith("voluntary_ctxt_switches:"))
                sum += line.mid(line.indexOf(':') + 1).trimmed().toLongLong();
    }
    return sum;
}

ProcessActivity::ProcessActivity(qint64 pid, qint64 onlyThread)
    : m_pid(pid) {
    if (onlyThread > 0)
        m_threads = {QString::number(onlyThread)};
    const std::optional<quint64> id = syscallTracepointId();
    if (!id)
        m_whyNot = QStringLiteral("the kernel's raw_syscalls tracepoint is not readable here");
    for (const QString &tid : !id                   ? QStringList()
                              : m_threads.isEmpty() ? threadsOf(pid)
                                                    : m_threads) {
        perf_event_attr attr;
        std::memset(&attr, 0, sizeof attr);
        attr.size = sizeof attr;
        attr.type = PERF_TYPE_TRACEPOINT;
        attr.config = *id;
        const long fd =
            ::syscall(SYS_perf_event_open, &attr, pid_t(tid.toInt()), -1, -1, PERF_FLAG_FD_CLOEXEC);
        if (fd < 0) {
            m_whyNot = QStringLiteral("counting system calls was refused: %1")
                           .arg(QString::fromLocal8Bit(std::strerror(errno)));
            break;
        }
        m_counters.push_back(int(fd));
    }
    if (!m_whyNot.isEmpty()) {
        for (int fd : m_counters)
            ::close(fd);
        m_counters.clear();
    }
    m_wakeUpsBefore = voluntarySwitches();
}

ProcessActivity::~ProcessActivity() {
    for (int fd : m_counters)
        ::close(fd);
}

std::optional<qint64> ProcessActivity::syscalls() const {
    if (m_counters.empty())
        return std::nullopt;
    qint64 sum = 0;
    for (int fd : m_counters) {
        quint64 count = 0;
        if (::read(fd, &count, sizeof count) != ssize_t(sizeof count))
            return std::nullopt;
        sum += qint64(count);
    }
    return sum;
}

qint64 ProcessActivity::wakeUps() const {
    return voluntarySwitches() - m_wakeUpsBefore;
}

} // namespace tipscope::bench
