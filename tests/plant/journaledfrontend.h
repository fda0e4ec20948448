// A program that keeps a journal, on a line of its own: `tipscope-cli monitor --journal` or
// tipscope-agent, so that a test holds both to the same promise with the same steps. What it
// wrote is read back with the journal's own reader.
#pragma once

#include "agentprocess.h"
#include "journal/journalreader.h"

#include <QProcess>
#include <QTemporaryDir>

namespace tipscope::testing {

class JournaledFrontEnd {
public:
    enum class Kind { Monitor, Agent };

    explicit JournaledFrontEnd(Kind kind);
    ~JournaledFrontEnd();

    // On the line `tcpLine` ("host:port"); the agent publishes to the broker at `brokerPort`.
    [[nodiscard]] bool start(const QString &tcpLine, int brokerPort, QString *error);
    // Ends it as a person or a service manager would (Ctrl-C for monitor, SIGTERM for the
    // agent); its exit status, or -1 when it did not end by itself within 15 s.
    [[nodiscard]] int stop();

    [[nodiscard]] QString journalPath() const;
    // What it said on standard error (monitor) or in its log (the agent), kept whole.
    [[nodiscard]] QString log();
    // Monitor's standard output, kept whole.
    [[nodiscard]] QString output();

    // The journal's joints and events; empty while it cannot be read yet.
    [[nodiscard]] QList<journal::StoredJoint> joints() const;
    [[nodiscard]] QList<journal::StoredEvent> events(journal::JournalEvent::Kind kind) const;

private:
    Kind m_kind;
    QTemporaryDir m_dir;
    QProcess m_monitor;
    AgentProcess m_agent;
    QString m_said, m_printed;
};

} // namespace tipscope::testing
