// Where a broker password comes from (a file, an environment variable), and that it goes nowhere
// else: not into any log line (libmosquitto's own included), nor any error text, even when the
// broker refuses it again and again.
#include "mqtt/mqttsecret.h"
#include "mqtttesting.h"
#include "testmain.h"

#include <QLoggingCategory>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_mqttsecret {

using namespace tipscope::mqtt;
using namespace tipscope::testing;

namespace {

QStringList g_logLines;

void captureMessage(QtMsgType, const QMessageLogContext &context, const QString &message) {
    g_logLines << QString::fromUtf8(context.category) + QLatin1Char(' ') + message;
}

bool writeFile(const QString &path, const QByteArray &content) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(content) == content.size();
}

} // namespace

class TstMqttSecret : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void passwordIsTheFilesFirstLine();
    void unusablePasswordFilesAreRefusedByName_data();
    void unusablePasswordFilesAreRefusedByName();
    void passwordComesFromTheEnvironment();
    void unsetEnvironmentVariableIsRefusedByName();
    void passwordNeverAppearsInLogsOrErrors();
};

void TstMqttSecret::passwordIsTheFilesFirstLine() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("password"));
    QVERIFY(writeFile(path, "pa ss:word\r\nsecond line\n"));
    const auto secret = readSecretFile(path);
    QVERIFY2(secret, qPrintable(secret.error()));
    QCOMPARE(*secret, QByteArray("pa ss:word"));
}

void TstMqttSecret::unusablePasswordFilesAreRefusedByName_data() {
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("reason");
    QTest::newRow("missing") << QByteArray() << "does not exist";
    QTest::newRow("empty") << QByteArray("\n") << "is empty";
    QTest::newRow("too large") << QByteArray(5000, 'x') << "larger than 4096 bytes";
}

void TstMqttSecret::unusablePasswordFilesAreRefusedByName() {
    QFETCH(QByteArray, content);
    QFETCH(QString, reason);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("password"));
    if (!content.isNull())
        QVERIFY(writeFile(path, content));
    const auto secret = readSecretFile(path);
    QVERIFY(!secret);
    QVERIFY2(secret.error().contains(path) && secret.error().contains(reason),
             qPrintable(secret.error()));
}

void TstMqttSecret::passwordComesFromTheEnvironment() {
    qputenv("TIPSCOPE_TEST_MQTT_PASSWORD", "from-env\n");
    const auto secret = readSecretEnvironment(QStringLiteral("TIPSCOPE_TEST_MQTT_PASSWORD"));
    qunsetenv("TIPSCOPE_TEST_MQTT_PASSWORD");
    QVERIFY2(secret, qPrintable(secret.error()));
    QCOMPARE(*secret, QByteArray("from-env"));
}

void TstMqttSecret::unsetEnvironmentVariableIsRefusedByName() {
    const auto secret = readSecretEnvironment(QStringLiteral("TIPSCOPE_TEST_NO_SUCH_VARIABLE"));
    QVERIFY(!secret);
    QVERIFY2(secret.error().contains(QLatin1String("TIPSCOPE_TEST_NO_SUCH_VARIABLE")),
             qPrintable(secret.error()));
}

void TstMqttSecret::passwordNeverAppearsInLogsOrErrors() {
    const QString password = QStringLiteral("Never-Log-Me-42");
    BrokerOptions options;
    options.users.insert(QStringLiteral("agent"), QStringLiteral("the-right-one"));
    MosquittoBroker broker(options);
    TIPSCOPE_START_BROKER(broker);
    MqttSettings settings = brokerSettings(broker, QStringLiteral("agent"));
    settings.username = QStringLiteral("agent");
    settings.password = password.toUtf8();

    QStringList errors;
    g_logLines.clear();
    QLoggingCategory::setFilterRules(QStringLiteral("tipscope.mqtt*=true"));
    const QtMessageHandler previous = qInstallMessageHandler(captureMessage);
    {
        MqttClient client;
        connect(&client, &MqttClient::problemOccurred, this,
                [&](MqttProblem, const QString &text) { errors << text; });
        client.setSettings(settings);
        client.start();
        Q_UNUSED(QTest::qWaitFor([&] { return errors.size() >= 2; }, 10000));
        errors << client.problemText();
        client.stop();
    }
    qInstallMessageHandler(previous);
    QLoggingCategory::setFilterRules(QString());

    QVERIFY(errors.size() >= 3);
    // The capture worked: libmosquitto's CONNECT and our refusal are in it.
    QVERIFY(!g_logLines.filter(QStringLiteral("sending CONNECT")).isEmpty());
    QVERIFY(!g_logLines.filter(QStringLiteral("not authorised")).isEmpty());
    for (const QString &line : g_logLines + errors)
        QVERIFY2(!line.contains(password), qPrintable(line));
}

TIPSCOPE_TEST_GUILESS_MAIN(TstMqttSecret)

} // namespace tst_mqttsecret
#include "tst_mqttsecret.moc"
