#include "rabbitmqbroker.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QTcpServer>
#include <QThread>
#include <QUuid>
#include <pwd.h>
#include <unistd.h>

namespace tipscope::testing {

namespace {

const QString kBin = QStringLiteral("/usr/lib/rabbitmq/bin/");
const QString kServiceUser = QStringLiteral("rabbitmq");

// The ports at once, so none of them is handed out twice.
QList<int> freeLoopbackPorts(int count) {
    QList<QTcpServer *> servers;
    QList<int> ports;
    for (int i = 0; i < count; ++i) {
        auto *server = new QTcpServer;
        if (server->listen(QHostAddress::LocalHost, 0))
            ports.append(server->serverPort());
        servers.append(server);
    }
    qDeleteAll(servers);
    return ports;
}

bool runningAsRoot() {
    return geteuid() == 0;
}

bool giveToServiceUser(const QString &path) {
    if (!runningAsRoot())
        return true;
    const passwd *user = getpwnam(kServiceUser.toLocal8Bit().constData());
    return user && chown(path.toLocal8Bit().constData(), user->pw_uid, user->pw_gid) == 0;
}

bool writeOwned(const QString &path, const QByteArray &content, QFileDevice::Permissions mode,
                QString *error) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size()) {
        *error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    file.close();
    file.setPermissions(mode);
    if (!giveToServiceUser(path)) {
        *error = QStringLiteral("cannot give %1 to the user %2").arg(path, kServiceUser);
        return false;
    }
    return true;
}

} // namespace

RabbitMqBroker::RabbitMqBroker() {
    m_node = QStringLiteral("tipscope-test-%1@localhost").arg(QCoreApplication::applicationPid());
}

RabbitMqBroker::~RabbitMqBroker() {
    stop();
}

QString RabbitMqBroker::skipReason() {
    if (!QFile::exists(kBin + QStringLiteral("rabbitmq-server")))
        return QStringLiteral(
            "rabbitmq-server is not installed (scripts/install-deps installs it)");
    if (QDir(QStringLiteral("/usr/lib/rabbitmq/lib"))
            .entryList({QStringLiteral("rabbitmq_server-*")})
            .isEmpty())
        return QStringLiteral("RabbitMQ's plugins are missing");
    if (runningAsRoot() && !getpwnam(kServiceUser.toLocal8Bit().constData()))
        return QStringLiteral("the user rabbitmq does not exist");
    return {};
}

QString RabbitMqBroker::url() const {
    return QStringLiteral("amqp://127.0.0.1:%1").arg(m_amqpPort);
}

QString RabbitMqBroker::output() const {
    QFile log(m_dir.filePath(QStringLiteral("server.out")));
    return log.open(QIODevice::ReadOnly) ? QString::fromLocal8Bit(log.readAll().right(4000))
                                         : QString();
}

bool RabbitMqBroker::prepareFolder(QString *error) {
    if (!m_dir.isValid() || !giveToServiceUser(m_dir.path())) {
        *error = QStringLiteral("cannot prepare the node's folder");
        return false;
    }
    const auto owner = QFileDevice::ReadOwner | QFileDevice::WriteOwner;
    return writeOwned(m_dir.filePath(QStringLiteral(".erlang.cookie")),
                      QUuid::createUuid().toByteArray(QUuid::Id128), QFileDevice::ReadOwner,
                      error) &&
           writeOwned(m_dir.filePath(QStringLiteral("enabled_plugins")), "[rabbitmq_amqp1_0].\n",
                      owner, error) &&
           writeOwned(m_dir.filePath(QStringLiteral("rabbitmq-env.conf")), "", owner, error) &&
           (!m_tls || writeTlsConfig(error));
}

bool RabbitMqBroker::writeTlsConfig(QString *error) {
    // The node runs as its own user, which cannot read the test's folder: copies it owns.
    const auto owner = QFileDevice::ReadOwner | QFileDevice::WriteOwner;
    const auto copy = [&](const QString &from, const QString &name) {
        QFile file(from);
        if (!file.open(QIODevice::ReadOnly)) {
            *error = QStringLiteral("cannot read %1: %2").arg(from, file.errorString());
            return false;
        }
        return writeOwned(m_dir.filePath(name), file.readAll(), owner, error);
    };
    const QString conf = QStringLiteral("listeners.ssl.1 = 127.0.0.1:%1\n"
                                        "ssl_options.cacertfile = %2\n"
                                        "ssl_options.certfile = %3\n"
                                        "ssl_options.keyfile = %4\n"
                                        "ssl_options.verify = verify_peer\n"
                                        "ssl_options.fail_if_no_peer_cert = %5\n")
                             .arg(m_tlsPort)
                             .arg(m_dir.filePath(QStringLiteral("tls-ca.crt")),
                                  m_dir.filePath(QStringLiteral("tls-server.crt")),
                                  m_dir.filePath(QStringLiteral("tls-server.key")),
                                  m_tls->requireClientCertificate ? QStringLiteral("true")
                                                                  : QStringLiteral("false"));
    return copy(m_tls->caFile, QStringLiteral("tls-ca.crt")) &&
           copy(m_tls->certificateFile, QStringLiteral("tls-server.crt")) &&
           copy(m_tls->keyFile, QStringLiteral("tls-server.key")) &&
           writeOwned(m_dir.filePath(QStringLiteral("rabbitmq.conf")), conf.toUtf8(), owner, error);
}

QStringList RabbitMqBroker::environment() const {
    const QString dir = m_dir.path();
    return {QStringLiteral("HOME=%1").arg(dir),
            QStringLiteral("RABBITMQ_NODENAME=%1").arg(m_node),
            QStringLiteral("RABBITMQ_NODE_IP_ADDRESS=127.0.0.1"),
            QStringLiteral("RABBITMQ_NODE_PORT=%1").arg(m_amqpPort),
            QStringLiteral("RABBITMQ_DIST_PORT=%1").arg(m_distPort),
            QStringLiteral("ERL_EPMD_PORT=%1").arg(m_epmdPort),
            QStringLiteral("ERL_EPMD_ADDRESS=127.0.0.1"),
            QStringLiteral("RABBITMQ_SERVER_ADDITIONAL_ERL_ARGS=-kernel inet_dist_use_interface "
                           "{127,0,0,1}"),
            QStringLiteral("RABBITMQ_MNESIA_BASE=%1/mnesia").arg(dir),
            QStringLiteral("RABBITMQ_LOG_BASE=%1/log").arg(dir),
            QStringLiteral("RABBITMQ_ENABLED_PLUGINS_FILE=%1/enabled_plugins").arg(dir),
            QStringLiteral("RABBITMQ_CONFIG_FILE=%1/rabbitmq").arg(dir),
            QStringLiteral("RABBITMQ_ADVANCED_CONFIG_FILE=%1/advanced.config").arg(dir),
            QStringLiteral("RABBITMQ_PID_FILE=%1/node.pid").arg(dir),
            QStringLiteral("RABBITMQ_CONF_ENV_FILE=%1/rabbitmq-env.conf").arg(dir)};
}

QPair<QString, QStringList> RabbitMqBroker::command(const QString &tool,
                                                    const QStringList &arguments) const {
    QStringList all = environment();
    all << kBin + tool << arguments;
    if (runningAsRoot())
        return {QStringLiteral("runuser"),
                QStringList{QStringLiteral("-u"), kServiceUser, QStringLiteral("--"),
                            QStringLiteral("env")} +
                    all};
    return {QStringLiteral("env"), all};
}

bool RabbitMqBroker::control(const QStringList &arguments, QString *error, int timeoutMs) {
    const auto [program, args] = command(QStringLiteral("rabbitmqctl"),
                                         QStringList{QStringLiteral("-n"), m_node} + arguments);
    QProcess ctl;
    ctl.setProcessChannelMode(QProcess::MergedChannels);
    ctl.setWorkingDirectory(m_dir.path());
    ctl.start(program, args);
    if (!ctl.waitForFinished(timeoutMs) || ctl.exitStatus() != QProcess::NormalExit ||
        ctl.exitCode() != 0) {
        ctl.kill();
        ctl.waitForFinished(1000);
        *error = QStringLiteral("rabbitmqctl %1 failed: %2\n%3")
                     .arg(arguments.join(QLatin1Char(' ')), QString::fromLocal8Bit(ctl.readAll()),
                          output());
        return false;
    }
    return true;
}

bool RabbitMqBroker::start(QString *error) {
    if (m_running)
        return true;
    const int needed = m_tls ? 4 : 3;
    const QList<int> ports = freeLoopbackPorts(needed);
    if (ports.size() != needed) {
        *error = QStringLiteral("no free loopback ports");
        return false;
    }
    m_amqpPort = ports[0];
    m_distPort = ports[1];
    m_epmdPort = ports[2];
    m_tlsPort = m_tls ? ports[3] : 0;
    if (!prepareFolder(error))
        return false;
    const auto [program, args] = command(QStringLiteral("rabbitmq-server"), {});
    m_server.setProcessChannelMode(QProcess::MergedChannels);
    m_server.setStandardOutputFile(m_dir.filePath(QStringLiteral("server.out")));
    m_server.setWorkingDirectory(m_dir.path());
    m_server.start(program, args);
    if (!m_server.waitForStarted(10000)) {
        *error = QStringLiteral("cannot start rabbitmq-server: %1").arg(m_server.errorString());
        return false;
    }
    m_running = true;
    return awaitStartup(error);
}

bool RabbitMqBroker::awaitStartup(QString *error) {
    // await_startup gives up at once while the node has not yet registered with its epmd.
    const QDeadlineTimer deadline(90000);
    while (!control(
        {QStringLiteral("await_startup"), QStringLiteral("--timeout"), QStringLiteral("60")}, error,
        70000)) {
        if (deadline.hasExpired() || m_server.state() == QProcess::NotRunning)
            return false;
        QThread::msleep(500);
    }
    return true;
}

bool RabbitMqBroker::pause(QString *error) {
    return control({QStringLiteral("stop_app")}, error);
}

bool RabbitMqBroker::resume(QString *error) {
    return control({QStringLiteral("start_app")}, error) && awaitStartup(error);
}

void RabbitMqBroker::stop() {
    if (!m_running)
        return;
    m_running = false;
    QString ignored;
    if (!control({QStringLiteral("stop")}, &ignored, 30000))
        m_server.kill();
    m_server.waitForFinished(30000);
    // The node started an epmd of its own on its port; it outlives the node unless told.
    QProcess epmd;
    epmd.start(QStringLiteral("epmd"),
               {QStringLiteral("-port"), QString::number(m_epmdPort), QStringLiteral("-kill")});
    epmd.waitForFinished(10000);
}

} // namespace tipscope::testing
