// A real Mosquitto broker for tests: Debian's /usr/sbin/mosquitto on a free loopback port, with
// a configuration generated in a temporary folder, optionally a password file (made with
// mosquitto_passwd), an ACL file and a TLS listener (certificates from TestCertificates). It
// stops when destroyed, also when a test fails, and can be stopped and started again on the same
// port for outage tests, or frozen (SIGSTOP) to play a broker that no longer answers.
//
// A test that cannot run the broker (mosquitto or mosquitto_passwd missing) QSKIPs with
// skipReason(); scripts/install-deps installs both, so CI always runs these tests.
#pragma once

#include <QMap>
#include <QProcess>
#include <QString>
#include <QTemporaryDir>

namespace tipscope::testing {

class TestCertificates;

struct BrokerOptions {
    // User name to password; when not empty, anonymous clients are refused.
    QMap<QString, QString> users;
    // The ACL file's text (mosquitto's acl_file syntax); empty: no ACL.
    QString acl;
    // Serve TLS with these certificates instead of plain MQTT.
    const TestCertificates *tls = nullptr;
    bool requireClientCertificate = false;
    // Keep sessions, queued messages and retained ones across a stop() and start(), as a plant's
    // broker does: a persistent subscriber then misses nothing published while it reconnects.
    bool persistence = false;
};

class MosquittoBroker {
public:
    explicit MosquittoBroker(BrokerOptions options = {});
    ~MosquittoBroker();
    MosquittoBroker(const MosquittoBroker &) = delete;
    MosquittoBroker &operator=(const MosquittoBroker &) = delete;

    // Empty when the broker and its tools are installed, else why the test must skip.
    [[nodiscard]] static QString skipReason();

    // Picks a free port on the first start, keeps it afterwards; waits until it accepts.
    [[nodiscard]] bool start(QString *error);
    void stop();
    // SIGKILL, frozen or not: nothing more leaves the broker.
    void kill();
    void freeze();
    void thaw();
    [[nodiscard]] bool isRunning() const { return m_process.state() == QProcess::Running; }

    [[nodiscard]] int port() const { return m_port; }
    // Everything the broker printed so far (its log), for failure messages.
    [[nodiscard]] QString output() const;

private:
    [[nodiscard]] bool writeConfiguration(QString *error);
    [[nodiscard]] bool writePasswordFile(const QString &path, QString *error);
    [[nodiscard]] bool waitUntilListening(QString *error);

    BrokerOptions m_options;
    QTemporaryDir m_dir;
    QProcess m_process;
    int m_port = 0;
};

// Runs a program to its end; false with *error (its output included) when it fails.
[[nodiscard]] bool runTool(const QString &program, const QStringList &arguments, QString *error,
                           const QString &workingDirectory = QString());

} // namespace tipscope::testing
