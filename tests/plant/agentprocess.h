// A tipscope-agent for tests and benches: the built program run on a configuration written into a
// temporary folder (a workspace of TCP lines, the broker of the test, a journal of its own), with
// what it logs kept for failure messages. Stops with SIGTERM when destroyed, or is killed
// (SIGKILL).
#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

namespace tipscope::testing {

class AgentProcess {
public:
    AgentProcess();
    ~AgentProcess();

    // The configuration of a line "cell-1" reached at `tcpLine` ("demo": the built-in demo line,
    // which solders): `broker` is merged into the defaults (127.0.0.1:port, keep-alive 5 s,
    // retries at most a second apart); `extra` into the top level.
    void configure(const QString &tcpLine, int brokerPort, const QJsonObject &broker = {},
                   const QJsonObject &extra = {});
    // The same with a workspace of several lines, each {"name", "connection"} as a workspace
    // file has them (tcpLineJson() makes one).
    void configureLines(const QJsonArray &lines, int brokerPort, const QJsonObject &broker = {},
                        const QJsonObject &extra = {});
    [[nodiscard]] static QJsonObject tcpLineJson(const QString &name, const QString &address);
    [[nodiscard]] bool start(QString *error);
    // SIGTERM, then waits for the exit code.
    [[nodiscard]] int stop();
    void kill();

    [[nodiscard]] QString folder() const { return m_dir.path(); }
    [[nodiscard]] QString journalPath() const;
    [[nodiscard]] QString log();
    [[nodiscard]] QProcess &process() { return m_process; }

private:
    QTemporaryDir m_dir;
    QProcess m_process;
    QString m_log;
};

} // namespace tipscope::testing
