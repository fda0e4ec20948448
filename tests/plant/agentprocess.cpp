#include "agentprocess.h"

#include "ptyfixtures.h"

#include <QFile>
#include <QJsonDocument>
#include <csignal>

namespace tipscope::testing {

namespace {
void writeJson(const QString &path, const QJsonObject &json) {
    QFile file(path);
    if (file.open(QIODevice::WriteOnly))
        file.write(QJsonDocument(json).toJson());
}
} // namespace

AgentProcess::AgentProcess() {
    m_process.setProcessChannelMode(QProcess::MergedChannels);
}

AgentProcess::~AgentProcess() {
    if (m_process.state() == QProcess::Running)
        (void)stop();
}

QJsonObject AgentProcess::tcpLineJson(const QString &name, const QString &address) {
    return {
        {QStringLiteral("name"), name},
        {QStringLiteral("connection"), QJsonObject{{QStringLiteral("kind"), QStringLiteral("tcp")},
                                                   {QStringLiteral("address"), address}}}};
}

void AgentProcess::configure(const QString &tcpLine, int brokerPort, const QJsonObject &broker,
                             const QJsonObject &extra) {
    const QJsonObject line =
        tcpLine == QLatin1String("demo")
            ? QJsonObject{{QStringLiteral("name"), QStringLiteral("cell-1")},
                          {QStringLiteral("connection"),
                           QJsonObject{{QStringLiteral("kind"), QStringLiteral("demo")}}}}
            : tcpLineJson(QStringLiteral("cell-1"), tcpLine);
    configureLines({line}, brokerPort, broker, extra);
}

void AgentProcess::configureLines(const QJsonArray &lines, int brokerPort,
                                  const QJsonObject &broker, const QJsonObject &extra) {
    writeJson(m_dir.filePath(QStringLiteral("lines.json")),
              {{QStringLiteral("format"), QStringLiteral("tipscope-workspace")},
               {QStringLiteral("version"), 1},
               {QStringLiteral("lines"), lines}});
    QJsonObject brokerJson{{QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                           {QStringLiteral("port"), brokerPort},
                           {QStringLiteral("client_id"), QStringLiteral("test-agent")},
                           {QStringLiteral("keep_alive_s"), 5},
                           {QStringLiteral("retry_max_s"), 1}};
    for (auto it = broker.begin(); it != broker.end(); ++it)
        brokerJson.insert(it.key(), it.value());
    QJsonObject config{{QStringLiteral("format"), QStringLiteral("tipscope-agent")},
                       {QStringLiteral("version"), 1},
                       {QStringLiteral("site"), QStringLiteral("Test Site")},
                       {QStringLiteral("workspace"), QStringLiteral("lines.json")},
                       {QStringLiteral("journal"), QStringLiteral("journal.sqlite")},
                       {QStringLiteral("broker"), brokerJson}};
    for (auto it = extra.begin(); it != extra.end(); ++it)
        config.insert(it.key(), it.value());
    writeJson(m_dir.filePath(QStringLiteral("agent.json")), config);
}

bool AgentProcess::start(QString *error) {
    m_process.start(binaryPath(QStringLiteral("tipscope-agent")),
                    {QStringLiteral("--config"), m_dir.filePath(QStringLiteral("agent.json"))});
    if (!m_process.waitForStarted(5000)) {
        *error = QStringLiteral("tipscope-agent did not start: ") + m_process.errorString();
        return false;
    }
    return true;
}

int AgentProcess::stop() {
    ::kill(pid_t(m_process.processId()), SIGTERM);
    if (!m_process.waitForFinished(15000)) {
        m_process.kill();
        m_process.waitForFinished(5000);
        return -1;
    }
    return m_process.exitStatus() == QProcess::NormalExit ? m_process.exitCode() : -1;
}

void AgentProcess::kill() {
    m_process.kill(); // SIGKILL: nothing more leaves the agent
    m_process.waitForFinished(5000);
}

QString AgentProcess::journalPath() const {
    return m_dir.filePath(QStringLiteral("journal.sqlite"));
}

QString AgentProcess::log() {
    m_log += QString::fromUtf8(m_process.readAll());
    return m_log;
}

} // namespace tipscope::testing
