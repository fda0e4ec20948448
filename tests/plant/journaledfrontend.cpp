#include "journaledfrontend.h"

#include "ptyfixtures.h"

#include <csignal>

namespace tipscope::testing {

JournaledFrontEnd::JournaledFrontEnd(Kind kind)
    : m_kind(kind) {
    QObject::connect(&m_monitor, &QProcess::readyReadStandardError, &m_monitor, [this] {
        m_said += QString::fromLocal8Bit(m_monitor.readAllStandardError());
    });
    QObject::connect(&m_monitor, &QProcess::readyReadStandardOutput, &m_monitor,
                     [this] { m_printed += QString::fromUtf8(m_monitor.readAllStandardOutput()); });
}

JournaledFrontEnd::~JournaledFrontEnd() {
    if (m_monitor.state() != QProcess::NotRunning) {
        m_monitor.kill();
        m_monitor.waitForFinished(5000);
    }
}

bool JournaledFrontEnd::start(const QString &tcpLine, int brokerPort, QString *error) {
    if (m_kind == Kind::Agent) {
        m_agent.configure(tcpLine, brokerPort);
        return m_agent.start(error);
    }
    m_monitor.start(binaryPath(QStringLiteral("tipscope-cli")),
                    {QStringLiteral("--tcp"), tcpLine, QStringLiteral("monitor"),
                     QStringLiteral("--journal"), journalPath()});
    if (m_monitor.waitForStarted(5000))
        return true;
    *error = m_monitor.errorString();
    return false;
}

int JournaledFrontEnd::stop() {
    if (m_kind == Kind::Agent)
        return m_agent.stop();
    ::kill(pid_t(m_monitor.processId()), SIGINT);
    if (!m_monitor.waitForFinished(15000) || m_monitor.exitStatus() != QProcess::NormalExit)
        return -1;
    m_said += QString::fromLocal8Bit(m_monitor.readAllStandardError());
    m_printed += QString::fromUtf8(m_monitor.readAllStandardOutput());
    return m_monitor.exitCode();
}

QString JournaledFrontEnd::journalPath() const {
    return m_kind == Kind::Agent ? m_agent.journalPath()
                                 : m_dir.filePath(QStringLiteral("journal.sqlite"));
}

QString JournaledFrontEnd::log() {
    return m_kind == Kind::Agent ? m_agent.log() : m_said;
}

QString JournaledFrontEnd::output() {
    return m_printed;
}

QList<journal::StoredJoint> JournaledFrontEnd::joints() const {
    journal::JournalReader reader;
    if (!reader.open(journalPath()))
        return {};
    const auto joints = reader.joints({});
    return joints ? joints.value() : QList<journal::StoredJoint>();
}

QList<journal::StoredEvent> JournaledFrontEnd::events(journal::JournalEvent::Kind kind) const {
    journal::JournalReader reader;
    if (!reader.open(journalPath()))
        return {};
    journal::EventFilter filter;
    filter.kinds = {kind};
    const auto events = reader.events(filter);
    return events ? events.value() : QList<journal::StoredEvent>();
}

} // namespace tipscope::testing
