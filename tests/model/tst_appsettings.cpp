// Settings from an older version or edited by hand fall back to defaults; they never reach the
// line.
#include "model/appsettings.h"
#include "testmain.h"

#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

namespace tst_appsettings {

using namespace tipscope::model;

class TestAppSettings : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void roundTripsEverything();
    void malformedValuesFallBackToDefaults_data();
    void malformedValuesFallBackToDefaults();
    void unusableConnectionsAreRefusedWithAReason();
};

void TestAppSettings::roundTripsEverything() {
    QTemporaryDir dir;
    QSettings s(dir.filePath(QStringLiteral("a.ini")), QSettings::IniFormat);
    AppSettings a;
    a.kind = AppSettings::Kind::Tcp;
    a.tcpAddress = QStringLiteral("10.0.0.5:4001");
    a.baud = 9600;
    a.parity = QStringLiteral("even");
    a.addressing = Session::Addressing::With;
    a.targetAddress = 7;
    a.unit = TemperatureUnit::Fahrenheit;
    a.liveMs = 500;
    a.language = QStringLiteral("de");
    a.fullRateMinutes = 45;
    a.historyHours = 48;
    a.save(s);
    const AppSettings b = AppSettings::load(s);
    QCOMPARE(int(b.kind), int(a.kind));
    QCOMPARE(b.tcpAddress, a.tcpAddress);
    QCOMPARE(b.baud, 9600);
    QCOMPARE(b.parity, QStringLiteral("even"));
    QCOMPARE(int(b.addressing), int(Session::Addressing::With));
    QCOMPARE(b.targetAddress, 7);
    QCOMPARE(int(b.unit), int(TemperatureUnit::Fahrenheit));
    QCOMPARE(b.liveMs, 500);
    QCOMPARE(b.language, QStringLiteral("de"));
    QCOMPARE(b.fullRateMinutes, 45);
    QCOMPARE(b.historyHours, 48);
    QCOMPARE(b.telemetryTiers().fullRateMs, qint64(45) * 60 * 1000);
    QCOMPARE(b.telemetryTiers().historyMs, qint64(48) * 3600 * 1000);
}

void TestAppSettings::malformedValuesFallBackToDefaults_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QVariant>("value");
    QTest::newRow("kind") << "connection/kind" << QVariant(QStringLiteral("carrier-pigeon"));
    QTest::newRow("baud text") << "line/baud" << QVariant(QStringLiteral("fast"));
    QTest::newRow("baud negative") << "line/baud" << QVariant(-5);
    QTest::newRow("parity") << "line/parity" << QVariant(QStringLiteral("mark"));
    QTest::newRow("address") << "line/targetAddress" << QVariant(250);
    QTest::newRow("unit") << "prefs/temperatureUnit" << QVariant(QStringLiteral("K"));
    QTest::newRow("poll") << "poll/liveMs" << QVariant(0);
    QTest::newRow("retries") << "link/retries" << QVariant(1000);
    QTest::newRow("language") << "ui/language" << QVariant(QStringLiteral("tlh"));
    QTest::newRow("tcp") << "connection/tcp" << QVariant(QStringLiteral("nohost"));
    QTest::newRow("binary") << "line/baud" << QVariant(QByteArray("\xff\xfe\x00", 3));
    QTest::newRow("full rate") << "telemetry/fullRateMinutes" << QVariant(0);
    QTest::newRow("history") << "telemetry/historyHours" << QVariant(100000);
}

void TestAppSettings::malformedValuesFallBackToDefaults() {
    QFETCH(QString, key);
    QFETCH(QVariant, value);
    QTemporaryDir dir;
    QSettings s(dir.filePath(QStringLiteral("b.ini")), QSettings::IniFormat);
    s.setValue(key, value);
    const AppSettings loaded = AppSettings::load(s);
    const AppSettings defaults;
    QCOMPARE(int(loaded.kind), int(defaults.kind));
    QCOMPARE(loaded.baud, defaults.baud);
    QCOMPARE(loaded.parity, defaults.parity);
    QCOMPARE(loaded.targetAddress, defaults.targetAddress);
    QCOMPARE(int(loaded.unit), int(defaults.unit));
    QCOMPARE(loaded.liveMs, defaults.liveMs);
    QCOMPARE(loaded.retries, defaults.retries);
    QCOMPARE(loaded.language, defaults.language);
    QCOMPARE(loaded.tcpAddress, defaults.tcpAddress);
    QCOMPARE(loaded.fullRateMinutes, defaults.fullRateMinutes);
    QCOMPARE(loaded.historyHours, defaults.historyHours);
    QCOMPARE(loaded.telemetryTiers(), TelemetryTiers());
}

void TestAppSettings::unusableConnectionsAreRefusedWithAReason() {
    AppSettings a;
    a.kind = AppSettings::Kind::Serial;
    a.serialPort = QStringLiteral("  ");
    const auto serial = a.sessionSettings();
    QVERIFY(!serial);
    QVERIFY(serial.error().contains(QStringLiteral("serial port")));
    a.kind = AppSettings::Kind::Tcp;
    a.tcpAddress = QStringLiteral("host:99999");
    const auto tcp = a.sessionSettings();
    QVERIFY(!tcp);
    QVERIFY(tcp.error().contains(QStringLiteral("HOST:PORT")));
    a.kind = AppSettings::Kind::Demo;
    const auto demo = a.sessionSettings();
    QVERIFY2(demo, qPrintable(demo.error()));
    QVERIFY(demo->demoActivity); // the GUI's demo is at work, so its charts show something
}

TIPSCOPE_TEST_GUILESS_MAIN(TestAppSettings)

} // namespace tst_appsettings
#include "tst_appsettings.moc"
