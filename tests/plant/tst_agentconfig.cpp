// The agent's configuration file: defaults, relative paths, the password from a file or the
// environment (never from the file itself), and every refusal naming the field, checked before
// anything connects.
#include "plant/agentconfig.h"
#include "testmain.h"

#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

namespace tst_agentconfig {

using namespace tipscope::plant;

namespace {
void write(const QString &path, const QByteArray &text) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
}
} // namespace

class TestAgentConfig : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    QString path(const QString &name) const { return m_dir.filePath(name); }

    tipscope::base::Outcome<AgentConfig> load(const QByteArray &json) {
        write(path(QStringLiteral("agent.json")), json);
        return AgentConfig::load(path(QStringLiteral("agent.json")));
    }

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        write(path(QStringLiteral("lines.json")),
              R"({"format": "tipscope-workspace", "version": 1,
                  "lines": [{"name": "demo", "connection": {"kind": "demo"}}]})");
        write(path(QStringLiteral("secret")), "s3cret\n");
    }

    void aSmallFileGetsTheDefaults() {
        const auto c = load(R"({"format": "tipscope-agent", "version": 1,
                                "workspace": "lines.json"})");
        QVERIFY2(c, qPrintable(c.error()));
        QCOMPARE(c->site, QStringLiteral("site"));
        QCOMPARE(c->workspacePath, path(QStringLiteral("lines.json")));
        QCOMPARE(c->workspace.lines.size(), 1);
        QCOMPARE(c->broker.host, QStringLiteral("localhost"));
        QCOMPARE(c->broker.port, 1883);
        QCOMPARE(c->live.intervalMs, 1000);
        QCOMPARE(c->live.batchMs, 0);
        QCOMPARE(c->countersIntervalS, 600);
        QVERIFY(!c->remoteApply);
        QVERIFY(c->journalPath.isEmpty());
        QVERIFY(c->broker.password.isEmpty());
    }

    void everyFieldIsRead() {
        const auto c = load(R"({"format": "tipscope-agent", "version": 1, "site": "Plant A",
            "workspace": "lines.json", "journal": "data/journal.sqlite",
            "broker": {"host": "mqtt.plant", "port": 8883, "client_id": "line-7",
                       "keep_alive_s": 20, "retry_max_s": 10, "username": "line7",
                       "password_file": "secret", "protocol": "5",
                       "tls": {"ca_file": "ca.pem", "cert_file": "c.pem", "key_file": "k.pem"}},
            "live": {"interval_ms": 250, "batch_ms": 5000}, "counters_interval_s": 60,
            "remote_apply": true})");
        QVERIFY2(c, qPrintable(c.error()));
        QCOMPARE(c->site, QStringLiteral("Plant A"));
        QCOMPARE(c->journalPath, path(QStringLiteral("data/journal.sqlite")));
        QCOMPARE(c->broker.host, QStringLiteral("mqtt.plant"));
        QCOMPARE(c->broker.port, 8883);
        QCOMPARE(c->broker.clientId, QStringLiteral("line-7"));
        QCOMPARE(c->broker.keepAliveSeconds, 20);
        QCOMPARE(c->broker.retryMaxMs, 10000);
        QCOMPARE(c->broker.username, QStringLiteral("line7"));
        QCOMPARE(c->broker.password, QByteArray("s3cret"));
        QVERIFY(!c->passwordSource.contains(QLatin1String("s3cret")));
        QVERIFY(c->broker.protocol == tipscope::mqtt::MqttProtocol::V5);
        QCOMPARE(c->broker.tls.caFile, path(QStringLiteral("ca.pem")));
        QCOMPARE(c->live.intervalMs, 250);
        QCOMPARE(c->live.batchMs, 5000);
        QCOMPARE(c->countersIntervalS, 60);
        QVERIFY(c->remoteApply);
    }

    void theCfxSectionIsReadWithItsOwnPassword() {
        const auto c = load(R"({"format": "tipscope-agent", "version": 1,
            "workspace": "lines.json",
            "cfx": {"host": "mes.plant", "port": 5671, "address": "/exchange/cfx/line7",
                    "request_address": "/queue/line7-requests", "username": "cfx", "password_file": "secret", "gzip": false,
                    "heartbeat_s": 30, "retry_max_s": 20, "vendor": "JBC",
                    "tls": {"enabled": true, "ca_file": "ca.pem"}}})");
        QVERIFY2(c, qPrintable(c.error()));
        QVERIFY(c->cfx.has_value());
        QCOMPARE(c->cfx->host, QStringLiteral("mes.plant"));
        QCOMPARE(c->cfx->port, 5671);
        QCOMPARE(c->cfx->address, QStringLiteral("/exchange/cfx/line7"));
        QCOMPARE(c->cfx->requestAddress, QStringLiteral("/queue/line7-requests"));
        QCOMPARE(c->cfx->password, QByteArray("s3cret"));
        QVERIFY(!c->cfxPasswordSource.contains(QLatin1String("s3cret")));
        QVERIFY(c->cfx->codec == tipscope::cfx::Codec::Raw);
        QCOMPARE(c->cfx->heartbeatS, 30);
        QCOMPARE(c->cfx->retryMaxS, 20);
        QVERIFY(c->cfx->tls);
        QCOMPARE(c->cfx->caFile, path(QStringLiteral("ca.pem")));
        const auto none = load(R"({"format": "tipscope-agent", "version": 1,
                                   "workspace": "lines.json"})");
        QVERIFY2(none, qPrintable(none.error()));
        QVERIFY(!none->cfx.has_value());
        QVERIFY(none->mqtt);
        // CFX alone: no MQTT broker, none of its fields checked.
        const auto cfxOnly = load(R"({"format": "tipscope-agent", "version": 1,
                                      "workspace": "lines.json", "broker": false,
                                      "cfx": {"host": "mes.plant"}})");
        QVERIFY2(cfxOnly, qPrintable(cfxOnly.error()));
        QVERIFY(!cfxOnly->mqtt);
        QCOMPARE(cfxOnly->cfx->host, QStringLiteral("mes.plant"));
    }

    void thePasswordMayComeFromTheEnvironment() {
        qputenv("TIPSCOPE_TEST_BROKER_PASSWORD", "from-env");
        const auto c = load(R"({"format": "tipscope-agent", "version": 1,
            "workspace": "lines.json", "broker": {"username": "u",
            "password_env": "TIPSCOPE_TEST_BROKER_PASSWORD"}})");
        QVERIFY2(c, qPrintable(c.error()));
        QCOMPARE(c->broker.password, QByteArray("from-env"));
        qunsetenv("TIPSCOPE_TEST_BROKER_PASSWORD");
        const auto unset = load(R"({"format": "tipscope-agent", "version": 1,
            "workspace": "lines.json", "broker": {"password_env": "TIPSCOPE_TEST_BROKER_PASSWORD"}})");
        QVERIFY(!unset);
        QVERIFY2(unset.error().contains(QLatin1String("TIPSCOPE_TEST_BROKER_PASSWORD")),
                 qPrintable(unset.error()));
    }

    void refusals_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("named");
        QTest::newRow("not an agent file")
            << QByteArray(R"({"format": "tipscope-workspace", "version": 1})") << "format";
        QTest::newRow("later version")
            << QByteArray(
                   R"({"format": "tipscope-agent", "version": 9, "workspace": "lines.json"})")
            << "version 9";
        QTest::newRow("no workspace")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1})") << "workspace";
        QTest::newRow("missing workspace")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1, "workspace": "gone.json"})")
            << "gone.json";
        QTest::newRow("port out of range")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json",
                              "broker": {"port": 70000}})")
            << "broker.port";
        QTest::newRow("interval of the wrong kind")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json",
                              "live": {"interval_ms": "fast"}})")
            << "live.interval_ms";
        QTest::newRow("two password sources")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json",
                              "broker": {"password_file": "secret", "password_env": "X"}})")
            << "password_env";
        QTest::newRow("missing password file")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json",
                              "broker": {"password_file": "nothing-here"}})")
            << "nothing-here";
        QTest::newRow("unknown protocol")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json",
                              "broker": {"protocol": "4"}})")
            << "broker.protocol";
        QTest::newRow("remote apply not a flag")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json",
                              "remote_apply": "yes"})")
            << "remote_apply";
        QTest::newRow("a list") << QByteArray("[1, 2]") << "list";
        QTest::newRow("published nowhere")
            << QByteArray(R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json",
                              "broker": false})")
            << "a cfx section must say";
        const QByteArray cfx =
            R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json", "cfx": )";
        QTest::newRow("cfx without a host") << cfx + R"({"port": 5672}})"
                                            << "cfx.host";
        QTest::newRow("cfx address without its slash")
            << cfx + R"({"host": "h", "address": "exchange/cfx"}})"
            << "cfx.address";
        QTest::newRow("cfx requests from an exchange, which keeps none")
            << cfx + R"({"host": "h", "request_address": "/exchange/amq.topic"}})"
            << "cfx.request_address";
        QTest::newRow("cfx heartbeat beyond five minutes")
            << cfx + R"({"host": "h", "heartbeat_s": 301}})"
            << "cfx.heartbeat_s";
        QTest::newRow("cfx certificate without its key")
            << cfx + R"({"host": "h", "tls": {"cert_file": "c.pem"}}})"
            << "cfx.tls.cert_file";
        QTest::newRow("cfx not an object") << cfx + R"("amqp://h"})"
                                           << "cfx must be an object";
        QTest::newRow("cfx password missing")
            << cfx + R"({"host": "h", "password_env": "TIPSCOPE_TEST_NO_SUCH_VARIABLE"}})"
            << "TIPSCOPE_TEST_NO_SUCH_VARIABLE";
        const QByteArray head =
            R"({"format": "tipscope-agent", "version": 1, "workspace": "lines.json", "site": )";
        QTest::newRow("a site of 100,000 characters")
            << head + '"' + QByteArray(100000, 'x') + "\"}"
            << "site must be at most 64 characters long, not 100000";
        QTest::newRow("a site with an escape sequence") << head + "\"plant\\u001b[2J\"}"
                                                        << "site must not hold control characters";
    }
    void refusals() {
        QFETCH(QByteArray, json);
        QFETCH(QString, named);
        const auto c = load(json);
        QVERIFY(!c);
        QVERIFY2(c.error().contains(named), qPrintable(c.error()));
        QVERIFY2(c.error().contains(path(QStringLiteral("agent.json"))) ||
                     c.error().contains(QLatin1String("gone.json")),
                 qPrintable(c.error()));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestAgentConfig)

} // namespace tst_agentconfig
#include "tst_agentconfig.moc"
