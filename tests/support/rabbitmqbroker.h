// A real RabbitMQ node for tests: Debian's rabbitmq-server with its AMQP 1.0 plugin, on free
// loopback ports (AMQP, Erlang distribution and epmd), with its own node name, data folder and
// cookie in a temporary folder, so it never meets the system's node nor another test's. Run as
// root, Debian's server runs as the user rabbitmq: the folder is handed to that user and the
// node started as it. start() returns once `rabbitmqctl await_startup` says the node is up (a
// node answers a ping before its AMQP listener is); the destructor stops the node and its epmd.
// pause() and resume() stop and start the node's applications (its listeners and connections)
// for outage tests, keeping the node, its queues and its ports. With setTls() before start() the
// node also listens with TLS (amqps) on tlsPort(), its certificate and CA copied into its folder.
//
// A test that cannot run the node (the server or the plugin missing) QSKIPs with skipReason();
// scripts/install-deps installs both.
#pragma once

#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QTemporaryDir>
#include <optional>

namespace tipscope::testing {

class RabbitMqBroker {
public:
    RabbitMqBroker();
    ~RabbitMqBroker();
    RabbitMqBroker(const RabbitMqBroker &) = delete;
    RabbitMqBroker &operator=(const RabbitMqBroker &) = delete;

    [[nodiscard]] static QString skipReason();

    struct Tls {
        QString caFile;
        QString certificateFile;
        QString keyFile;
        bool requireClientCertificate = false; // signed by caFile
    };
    void setTls(const Tls &tls) { m_tls = tls; }

    [[nodiscard]] bool start(QString *error);
    void stop();
    [[nodiscard]] bool pause(QString *error);
    [[nodiscard]] bool resume(QString *error);
    // Runs rabbitmqctl with `arguments` against this node.
    [[nodiscard]] bool control(const QStringList &arguments, QString *error, int timeoutMs = 60000);

    [[nodiscard]] int port() const { return m_amqpPort; }
    [[nodiscard]] int tlsPort() const { return m_tlsPort; }
    [[nodiscard]] QString url() const;
    // The node's log so far, for failure messages.
    [[nodiscard]] QString output() const;

private:
    [[nodiscard]] bool prepareFolder(QString *error);
    [[nodiscard]] bool writeTlsConfig(QString *error);
    [[nodiscard]] bool awaitStartup(QString *error);
    [[nodiscard]] QStringList environment() const;
    // The program and arguments that run `tool` with this node's environment, as the user the
    // node runs as.
    [[nodiscard]] QPair<QString, QStringList> command(const QString &tool,
                                                      const QStringList &arguments) const;

    QTemporaryDir m_dir;
    QProcess m_server;
    QString m_node;
    int m_amqpPort = 0;
    int m_distPort = 0;
    int m_epmdPort = 0;
    std::optional<Tls> m_tls;
    int m_tlsPort = 0;
    bool m_running = false;
};

} // namespace tipscope::testing
