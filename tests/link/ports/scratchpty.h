// ScratchPty: a real pseudo terminal for tests, the nearest thing to a serial port that exists
// in a container. The master stays open for the object's lifetime (so the slave stays valid);
// holdInChild() opens the slave in a separate `sleep` process, as minicom or a second TipScope
// would hold a real adapter. The child is killed when the object is destroyed.
#pragma once

#include <QProcess>
#include <QString>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

class ScratchPty {
public:
    ScratchPty() {
        m_master = posix_openpt(O_RDWR | O_NOCTTY);
        if (m_master >= 0 && grantpt(m_master) == 0 && unlockpt(m_master) == 0)
            m_slave = QString::fromLocal8Bit(ptsname(m_master));
    }
    ~ScratchPty() {
        if (m_holder.state() != QProcess::NotRunning) {
            m_holder.kill();
            m_holder.waitForFinished(3000);
        }
        if (m_master >= 0)
            ::close(m_master);
    }
    ScratchPty(const ScratchPty &) = delete;
    ScratchPty &operator=(const ScratchPty &) = delete;

    // Empty if the system has no PTYs.
    [[nodiscard]] QString slavePath() const { return m_slave; }

    // Starts `sleep` with the slave as its standard input; returns its PID, or 0.
    qint64 holdInChild() {
        // exec, so the PID QProcess reports is the process that holds the slave.
        m_holder.start(QStringLiteral("sh"),
                       {QStringLiteral("-c"), QStringLiteral("exec sleep 30 < '%1'").arg(m_slave)});
        return m_holder.waitForStarted(5000) ? m_holder.processId() : 0;
    }

private:
    int m_master = -1;
    QString m_slave;
    QProcess m_holder;
};
