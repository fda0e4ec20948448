// tipscope-agent to a broker that takes TLS only, with a client certificate and a password both
// required, everything set in the agent's configuration file as a plant's would be (the CA, the
// certificate and key, the user, the password in a file of its own). mosquitto_sub, an
// independent client with its own certificate and user, sees the agent's retained status and info;
// an agent given the wrong CA says it is a certificate problem and goes on polling; neither log
// holds the password.
#include "../mqtt/mqtttesting.h"
#include "agentprocess.h"
#include "mosquittobroker.h"
#include "ptyfixtures.h"
#include "testcertificates.h"
#include "testmain.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

namespace tst_agenttls {

using namespace tipscope::testing;

namespace {

const QString kRoot = QStringLiteral("tipscope/v1/test_site/cell-1/01-dme");
const QString kSecret = QStringLiteral("agent-tls-s3cret");

} // namespace

class TestAgentTls : public QObject {
    Q_OBJECT
private:
    TestCertificates m_certificates;
    std::unique_ptr<MosquittoBroker> m_broker;
    SimProcess m_sim;
    QString m_line;

    // An agent on the simulator's line with the broker settings of a TLS plant, `caFile` its CA.
    bool startAgent(AgentProcess &agent, const QString &caFile) {
        QFile secret(agent.folder() + QStringLiteral("/broker-password"));
        if (!secret.open(QIODevice::WriteOnly) || secret.write(kSecret.toUtf8() + '\n') < 0)
            return false;
        secret.close();
        const QJsonObject tls{{QStringLiteral("ca_file"), caFile},
                              {QStringLiteral("cert_file"), m_certificates.clientCertificate()},
                              {QStringLiteral("key_file"), m_certificates.clientKey()}};
        // The server's certificate names localhost, and the agent checks the name.
        agent.configure(m_line, m_broker->port(),
                        {{QStringLiteral("host"), QStringLiteral("localhost")},
                         {QStringLiteral("username"), QStringLiteral("agent")},
                         {QStringLiteral("password_file"), QStringLiteral("broker-password")},
                         {QStringLiteral("tls"), tls}});
        QString error;
        if (!agent.start(&error)) {
            qWarning("%s", qPrintable(error));
            return false;
        }
        return true;
    }

    // One retained message of `topic` as mosquitto_sub over TLS gets it, or empty.
    QJsonObject retained(const QString &topic) {
        QProcess sub;
        sub.start(QStringLiteral("mosquitto_sub"),
                  {QStringLiteral("-h"),       QStringLiteral("localhost"),
                   QStringLiteral("-p"),       QString::number(m_broker->port()),
                   QStringLiteral("--cafile"), m_certificates.caFile(),
                   QStringLiteral("--cert"),   m_certificates.clientCertificate(),
                   QStringLiteral("--key"),    m_certificates.clientKey(),
                   QStringLiteral("-u"),       QStringLiteral("watcher"),
                   QStringLiteral("-P"),       QStringLiteral("watching"),
                   QStringLiteral("-C"),       QStringLiteral("1"),
                   QStringLiteral("-W"),       QStringLiteral("30"),
                   QStringLiteral("-t"),       topic});
        if (!sub.waitForFinished(40000))
            return {};
        return QJsonDocument::fromJson(sub.readAllStandardOutput()).object();
    }

private Q_SLOTS:
    void initTestCase() {
        const QString whyNot = TestCertificates::skipReason();
        if (!whyNot.isEmpty())
            QSKIP(qPrintable(whyNot));
        QString error;
        QVERIFY2(m_certificates.generate(&error), qPrintable(error));
        BrokerOptions options;
        options.tls = &m_certificates;
        options.requireClientCertificate = true;
        options.users.insert(QStringLiteral("agent"), kSecret);
        options.users.insert(QStringLiteral("watcher"), QStringLiteral("watching"));
        m_broker = std::make_unique<MosquittoBroker>(options);
        TIPSCOPE_START_BROKER(*m_broker);
        m_line = m_sim.start({QStringLiteral("--model"), QStringLiteral("DME"),
                              QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")},
                             &error);
        QVERIFY2(!m_line.isEmpty(), qPrintable(error));
    }

    void theAgentPublishesOverTlsWithItsCertificateAndPassword() {
        AgentProcess agent;
        QVERIFY(startAgent(agent, m_certificates.caFile()));
        const QJsonObject status = retained(kRoot + QStringLiteral("/status"));
        QVERIFY2(status.value(QStringLiteral("online")).toBool(),
                 qPrintable(agent.log() + m_broker->output()));
        const QJsonObject info = retained(kRoot + QStringLiteral("/info"));
        QCOMPARE(info.value(QStringLiteral("family")).toString(), QStringLiteral("DME"));
        // Said when it starts; read once the event loop has run.
        QVERIFY2(
            QTest::qWaitFor(
                [&] { return agent.log().contains(QLatin1String("with TLS as agent")); }, 5000),
            qPrintable(agent.log()));
        QVERIFY(!agent.log().contains(kSecret));
        QCOMPARE(agent.stop(), 0);
        // A clean stop says so on the same retained topic.
        QVERIFY(
            !retained(kRoot + QStringLiteral("/status")).value(QStringLiteral("online")).toBool());
    }

    void aWrongCaIsACertificateProblemAndPollingGoesOn() {
        AgentProcess agent;
        QVERIFY(startAgent(agent, m_certificates.otherCaFile()));
        QVERIFY2(
            QTest::qWaitFor(
                [&] { return agent.log().contains(QLatin1String("certificate verify failed")); },
                20000),
            qPrintable(agent.log()));
        QVERIFY2(
            QTest::qWaitFor([&] { return agent.log().contains(QLatin1String("1 device")); }, 20000),
            qPrintable(agent.log()));
        QVERIFY(!agent.log().contains(kSecret));
        QCOMPARE(agent.stop(), 0);
    }

    // Issue 38: --check passed a CA file that was missing or not PEM; the service then failed
    // at every connection instead.
    void checkRefusesACaFileThatIsMissingOrNotPem_data() {
        QTest::addColumn<QString>("ca");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("said");
        QTest::newRow("missing") << QStringLiteral("missing.crt") << 2
                                 << QStringLiteral("cannot be read");
        QTest::newRow("not PEM") << QStringLiteral("not-pem.crt") << 2
                                 << QStringLiteral("holds no PEM certificate");
        QTest::newRow("the right one") << m_certificates.caFile() << 0 << QStringLiteral("is good");
    }

    void checkRefusesACaFileThatIsMissingOrNotPem() {
        QFETCH(QString, ca);
        QFETCH(int, exitCode);
        QFETCH(QString, said);
        AgentProcess agent;
        QFile notPem(agent.folder() + QStringLiteral("/not-pem.crt"));
        QVERIFY(notPem.open(QIODevice::WriteOnly) && notPem.write(QByteArray(2048, '\x30')) > 0);
        notPem.close();
        agent.configure(m_line, m_broker->port(),
                        {{QStringLiteral("tls"), QJsonObject{{QStringLiteral("ca_file"), ca}}}});
        QProcess check;
        check.setProcessChannelMode(QProcess::MergedChannels);
        check.start(binaryPath(QStringLiteral("tipscope-agent")),
                    {QStringLiteral("--check"), QStringLiteral("--config"),
                     agent.folder() + QStringLiteral("/agent.json")});
        QVERIFY(check.waitForFinished(10000));
        const QString out = QString::fromUtf8(check.readAll());
        QVERIFY2(check.exitCode() == exitCode, qPrintable(out));
        QVERIFY2(out.contains(said), qPrintable(out));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestAgentTls)

} // namespace tst_agenttls
#include "tst_agenttls.moc"
