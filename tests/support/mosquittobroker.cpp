#include "mosquittobroker.h"

#include "testcertificates.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>
#include <pwd.h>
#include <signal.h>
#include <unistd.h>

namespace tipscope::testing {

namespace {

const QString kBroker = QStringLiteral("/usr/sbin/mosquitto");

int freeLoopbackPort() {
    QTcpServer server;
    if (!server.listen(QHostAddress::LocalHost, 0))
        return 0;
    return server.serverPort();
}

// Run as root, mosquitto switches to the user "mosquitto", who cannot read the temporary
// folder; naming the user we are keeps it as it is.
QString currentUserName() {
    const passwd *entry = getpwuid(geteuid());
    return entry ? QString::fromLocal8Bit(entry->pw_name) : QString();
}

bool writeFile(const QString &path, const QByteArray &content, QString *error) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size()) {
        *error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    file.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    return true;
}

} // namespace

bool runTool(const QString &program, const QStringList &arguments, QString *error,
             const QString &workingDirectory) {
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.setWorkingDirectory(workingDirectory);
    process.start(program, arguments);
    if (!process.waitForFinished(30000) || process.exitStatus() != QProcess::NormalExit ||
        process.exitCode() != 0) {
        *error =
            QStringLiteral("%1 failed: %2 %3")
                .arg(program, process.errorString(), QString::fromLocal8Bit(process.readAll()));
        return false;
    }
    return true;
}

MosquittoBroker::MosquittoBroker(BrokerOptions options)
    : m_options(std::move(options)) {
    // Files, not a pipe: a broker logging everything must never wait for a test to read. Its log
    // goes to a file of its own, written line by line; what it prints before (a configuration
    // error) to another.
    m_process.setProcessChannelMode(QProcess::MergedChannels);
    m_process.setStandardOutputFile(m_dir.filePath(QStringLiteral("mosquitto.out")),
                                    QIODevice::Append);
}

MosquittoBroker::~MosquittoBroker() {
    stop();
}

QString MosquittoBroker::skipReason() {
    if (!QFile::exists(kBroker))
        return QStringLiteral("mosquitto is not installed (scripts/install-deps installs it)");
    for (const QString &tool : {QStringLiteral("mosquitto_passwd"), QStringLiteral("mosquitto_sub"),
                                QStringLiteral("mosquitto_pub")}) {
        if (QStandardPaths::findExecutable(tool).isEmpty())
            return tool + QStringLiteral(" is not installed (scripts/install-deps installs "
                                         "mosquitto-clients and mosquitto)");
    }
    return {};
}

bool MosquittoBroker::writePasswordFile(const QString &path, QString *error) {
    if (!writeFile(path, {}, error))
        return false;
    for (auto it = m_options.users.cbegin(); it != m_options.users.cend(); ++it) {
        if (!runTool(QStringLiteral("mosquitto_passwd"),
                     {QStringLiteral("-b"), path, it.key(), it.value()}, error))
            return false;
    }
    return true;
}

bool MosquittoBroker::writeConfiguration(QString *error) {
    QStringList lines{
        QStringLiteral("listener %1 127.0.0.1").arg(m_port),
        QStringLiteral("user ") + currentUserName(),
        QStringLiteral("persistence %1").arg(m_options.persistence ? "true" : "false"),
        QStringLiteral("persistence_location ") + m_dir.path() + QLatin1Char('/'),
        QStringLiteral("log_dest file ") + m_dir.filePath(QStringLiteral("mosquitto.log")),
        QStringLiteral("log_type all"),
        QStringLiteral("allow_anonymous %1").arg(m_options.users.isEmpty() ? "true" : "false")};
    if (!m_options.users.isEmpty()) {
        const QString path = m_dir.filePath(QStringLiteral("passwords"));
        if (!writePasswordFile(path, error))
            return false;
        lines << QStringLiteral("password_file ") + path;
    }
    if (!m_options.acl.isEmpty()) {
        const QString path = m_dir.filePath(QStringLiteral("acl"));
        if (!writeFile(path, m_options.acl.toUtf8(), error))
            return false;
        lines << QStringLiteral("acl_file ") + path;
    }
    if (m_options.tls) {
        lines << QStringLiteral("cafile ") + m_options.tls->caFile()
              << QStringLiteral("certfile ") + m_options.tls->serverCertificate()
              << QStringLiteral("keyfile ") + m_options.tls->serverKey()
              << QStringLiteral("require_certificate %1")
                     .arg(m_options.requireClientCertificate ? "true" : "false");
    }
    return writeFile(m_dir.filePath(QStringLiteral("mosquitto.conf")),
                     lines.join(u'\n').toUtf8() + '\n', error);
}

bool MosquittoBroker::start(QString *error) {
    if (isRunning())
        return true;
    if (!m_dir.isValid()) {
        *error = QStringLiteral("no temporary folder for the broker");
        return false;
    }
    if (m_port == 0)
        m_port = freeLoopbackPort();
    if (m_port == 0 || !writeConfiguration(error))
        return false;
    m_process.start(kBroker,
                    {QStringLiteral("-c"), m_dir.filePath(QStringLiteral("mosquitto.conf"))});
    if (!m_process.waitForStarted(5000)) {
        *error = QStringLiteral("mosquitto did not start: ") + m_process.errorString();
        return false;
    }
    return waitUntilListening(error);
}

bool MosquittoBroker::waitUntilListening(QString *error) {
    const QDeadlineTimer deadline(10000);
    while (!deadline.hasExpired() && isRunning()) {
        QTcpSocket probe;
        probe.connectToHost(QHostAddress::LocalHost, quint16(m_port));
        if (probe.waitForConnected(200))
            return true;
        QThread::msleep(20);
    }
    *error = QStringLiteral("mosquitto does not listen on port %1: %2").arg(m_port).arg(output());
    return false;
}

void MosquittoBroker::stop() {
    if (m_process.state() == QProcess::NotRunning)
        return;
    thaw();
    m_process.terminate();
    if (!m_process.waitForFinished(5000))
        m_process.kill();
    m_process.waitForFinished(5000);
}

void MosquittoBroker::kill() {
    if (m_process.state() == QProcess::NotRunning)
        return;
    m_process.kill();
    m_process.waitForFinished(5000);
}

void MosquittoBroker::freeze() {
    if (isRunning())
        ::kill(pid_t(m_process.processId()), SIGSTOP);
}

void MosquittoBroker::thaw() {
    if (isRunning())
        ::kill(pid_t(m_process.processId()), SIGCONT);
}

QString MosquittoBroker::output() const {
    QString text;
    for (const QString &name : {QStringLiteral("mosquitto.out"), QStringLiteral("mosquitto.log")}) {
        QFile file(m_dir.filePath(name));
        if (file.open(QIODevice::ReadOnly))
            text += QString::fromLocal8Bit(file.readAll());
    }
    return text;
}

} // namespace tipscope::testing
