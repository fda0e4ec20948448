#include "ptyfixtures.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QThread>

namespace tipscope::testing {

QString binaryPath(const QString &name) {
    QString dir = qEnvironmentVariable("TIPSCOPE_BIN_DIR");
    if (dir.isEmpty())
        dir = QCoreApplication::applicationDirPath() + QStringLiteral("/../../bin");
    return QDir(dir).absoluteFilePath(name);
}

SocatPair::SocatPair() = default;

SocatPair::~SocatPair() {
    stop();
}

bool SocatPair::start(QString *error) {
    if (QStandardPaths::findExecutable(QStringLiteral("socat")).isEmpty()) {
        *error = QStringLiteral("socat is not installed (scripts/install-deps installs it)");
        return false;
    }
    m_socat.start(QStringLiteral("socat"), {QStringLiteral("pty,raw,echo=0,link=") + deviceEnd(),
                                            QStringLiteral("pty,raw,echo=0,link=") + hostEnd()});
    if (!m_socat.waitForStarted(5000)) {
        *error = QStringLiteral("socat did not start: ") + m_socat.errorString();
        return false;
    }
    const QDeadlineTimer deadline(10000);
    while (!deadline.hasExpired()) {
        if (QFileInfo::exists(deviceEnd()) && QFileInfo::exists(hostEnd()))
            return true;
        QThread::msleep(10);
    }
    *error = QStringLiteral("socat did not create its PTY links");
    return false;
}

void SocatPair::stop() {
    if (m_socat.state() != QProcess::NotRunning) {
        m_socat.terminate();
        if (!m_socat.waitForFinished(3000))
            m_socat.kill();
        m_socat.waitForFinished(3000);
    }
}

SimProcess::~SimProcess() {
    stop();
}

QString SimProcess::start(const QStringList &args, QString *error) {
    m_process.setProcessChannelMode(QProcess::SeparateChannels);
    m_process.start(binaryPath(QStringLiteral("tipscope-sim")), args);
    if (!m_process.waitForStarted(5000)) {
        *error = QStringLiteral("tipscope-sim did not start: ") + m_process.errorString();
        return {};
    }
    const QDeadlineTimer deadline(10000);
    while (!m_process.canReadLine() && !deadline.hasExpired() &&
           m_process.state() == QProcess::Running)
        m_process.waitForReadyRead(100);
    if (!m_process.canReadLine()) {
        *error = QStringLiteral("tipscope-sim printed no address: ") +
                 QString::fromLocal8Bit(m_process.readAllStandardError());
        return {};
    }
    return QString::fromLocal8Bit(m_process.readLine()).trimmed();
}

QString SimProcess::command(const QString &line) {
    m_process.write(line.toLocal8Bit() + '\n');
    const QDeadlineTimer deadline(5000);
    while (!m_process.canReadLine() && !deadline.hasExpired())
        m_process.waitForReadyRead(50);
    return QString::fromLocal8Bit(m_process.readLine()).trimmed();
}

void SimProcess::stop() {
    if (m_process.state() != QProcess::NotRunning) {
        m_process.terminate();
        if (!m_process.waitForFinished(3000))
            m_process.kill();
        m_process.waitForFinished(3000);
    }
}

} // namespace tipscope::testing
