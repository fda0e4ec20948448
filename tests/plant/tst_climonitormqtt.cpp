// tipscope-cli monitor --mqtt: the demo line published as the agent publishes it, seen by
// mosquitto_sub; a broker that cannot be reached is said and ends as a transport error.
#include "../mqtt/mqtttesting.h"
#include "mosquittobroker.h"
#include "ptyfixtures.h"
#include "testmain.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

namespace tst_climonitormqtt {

using namespace tipscope::testing;

class TestCliMonitorMqtt : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private Q_SLOTS:
    void theDemoLineIsPublished() {
        MosquittoBroker broker;
        TIPSCOPE_START_BROKER(broker);
        QProcess sub;
        startTool(sub, QStringLiteral("mosquitto_sub"), broker,
                  {QStringLiteral("-v"), QStringLiteral("-t"),
                   QStringLiteral("tipscope/v1/plant_a/demo/#")});
        QVERIFY(sub.waitForStarted());
        QTest::qWait(300); // subscribed before anything is published
        QProcess cli;
        cli.start(binaryPath(QStringLiteral("tipscope-cli")),
                  {QStringLiteral("--demo"), QStringLiteral("monitor"), QStringLiteral("--mqtt"),
                   QStringLiteral("127.0.0.1:%1").arg(broker.port()), QStringLiteral("--site"),
                   QStringLiteral("Plant A"), QStringLiteral("--duration"), QStringLiteral("5"),
                   QStringLiteral("--journal"), m_dir.filePath(QStringLiteral("journal.sqlite"))});
        QVERIFY(cli.waitForFinished(30000));
        const QString said = QString::fromUtf8(cli.readAllStandardOutput());
        QCOMPARE(cli.exitCode(), 0);
        QVERIFY2(said.contains(QLatin1String("Broker connected.")), qPrintable(said));
        QTest::qWait(500);
        sub.terminate();
        QVERIFY(sub.waitForFinished(5000));
        QMap<QString, QList<QJsonObject>> seen;
        for (const QByteArray &line : sub.readAllStandardOutput().split('\n')) {
            const qsizetype space = line.indexOf(' ');
            if (space > 0)
                seen[QString::fromUtf8(line.left(space))].append(
                    QJsonDocument::fromJson(line.mid(space + 1)).object());
        }
        const QString root = QStringLiteral("tipscope/v1/plant_a/demo/01-dme");
        QVERIFY2(seen.contains(root + QStringLiteral("/info")), qPrintable(seen.keys().join(' ')));
        QCOMPARE(seen.value(root + QStringLiteral("/info")).first().value("model").toString(),
                 QStringLiteral("DME-2C"));
        QVERIFY(seen.value(root + QStringLiteral("/status")).first().value("online").toBool());
        QVERIFY(!seen.value(root + QStringLiteral("/status")).last().value("online").toBool());
        // Five seconds at the default second: about five a port.
        QVERIFY(seen.value(root + QStringLiteral("/port/1/live")).size() >= 3);
        QVERIFY(seen.contains(QStringLiteral("tipscope/v1/plant_a/demo/10-sfr/feeder/live")));
    }

    void anUnreachableBrokerIsATransportError() {
        QProcess cli;
        cli.start(binaryPath(QStringLiteral("tipscope-cli")),
                  {QStringLiteral("--demo"), QStringLiteral("monitor"), QStringLiteral("--mqtt"),
                   QStringLiteral("127.0.0.1:1"), QStringLiteral("--duration"), QStringLiteral("2"),
                   QStringLiteral("--journal"), m_dir.filePath(QStringLiteral("journal.sqlite"))});
        QVERIFY(cli.waitForFinished(30000));
        QCOMPARE(cli.exitCode(), 5);
        QVERIFY(QString::fromUtf8(cli.readAllStandardOutput())
                    .contains(QLatin1String("No MQTT broker accepts connections")));
    }

    void aBadBrokerAddressIsAUsageError() {
        QProcess cli;
        cli.start(binaryPath(QStringLiteral("tipscope-cli")),
                  {QStringLiteral("--demo"), QStringLiteral("monitor"), QStringLiteral("--mqtt"),
                   QStringLiteral("no-port-here")});
        QVERIFY(cli.waitForFinished(30000));
        QCOMPARE(cli.exitCode(), 1);
        QVERIFY(QString::fromUtf8(cli.readAllStandardError()).contains(QLatin1String("--mqtt")));
    }

    void aBadCfxBrokerIsAUsageError_data() {
        QTest::addColumn<QStringList>("cfx");
        QTest::newRow("not an AMQP URL")
            << QStringList{QStringLiteral("--cfx"), QStringLiteral("mes:5672")};
        QTest::newRow("a password in the URL")
            << QStringList{QStringLiteral("--cfx"), QStringLiteral("amqp://u:secret@mes:5672")};
        QTest::newRow("an address without its slash")
            << QStringList{QStringLiteral("--cfx"), QStringLiteral("amqp://mes:5672"),
                           QStringLiteral("--cfx-address"), QStringLiteral("exchange/cfx")};
    }
    void aBadCfxBrokerIsAUsageError() {
        QFETCH(QStringList, cfx);
        QProcess cli;
        cli.start(binaryPath(QStringLiteral("tipscope-cli")),
                  QStringList{QStringLiteral("--demo"), QStringLiteral("monitor"),
                              QStringLiteral("--mqtt"), QStringLiteral("127.0.0.1:1")} +
                      cfx);
        QVERIFY(cli.waitForFinished(30000));
        QCOMPARE(cli.exitCode(), 1);
        const QString said = QString::fromUtf8(cli.readAllStandardError());
        QVERIFY2(said.contains(QLatin1String("--cfx")), qPrintable(said));
        QVERIFY2(!said.contains(QLatin1String("secret")), qPrintable(said));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestCliMonitorMqtt)

} // namespace tst_climonitormqtt
#include "tst_climonitormqtt.moc"
