// describePort() and the details it reads: kernel driver, FTDI latency timer, /dev/serial/by-id
// link, USB ids, and the advice and display name built from them. No real adapter exists here, so
// ScratchTree (scratchsysfs.h) lays out the sysfs and /dev files of a machine with adapters
// plugged in; a real PTY checks the path QSerialPortInfo does not list.
#include "link/ports/serialportlist.h"
#include "scratchpty.h"
#include "scratchsysfs.h"
#include "testmain.h"

#include <QSerialPort>
#include <QTest>

namespace tst_describeport {

using namespace tipscope::link;

namespace {

const QString kEmDash = QStringLiteral("\u2014");

const QString kFt232r = QStringLiteral("0403:6001 FTDI/FT232R USB UART/A10K1234");

} // namespace

class TestDescribePort : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void ftdiAdapterIsDescribedFromSysfs();
    void displayNameShowsDescriptionManufacturerAndIds();
    void ftdiAdapterWithDefaultLatencyGetsAdvice_data();
    void ftdiAdapterWithDefaultLatencyGetsAdvice();
    void ftdiAdapterAtOneMillisecondGetsNoAdvice();
    void otherUsbAdaptersHaveNoLatencyAndNoAdvice_data();
    void otherUsbAdaptersHaveNoLatencyAndNoAdvice();
    void acmDeviceGetsItsDriverFromTheInterface();
    void plainRs232PortIsListedWithoutVidPid();
    void uartBehindSerialBaseReportsTheHardwareDriver();
    void byIdLinkBelongsOnlyToItsOwnPort();
    void typedByIdPathDescribesTheAdapterBehindIt();
    void realPtyIsDescribedWithoutHardwareDetails();
    void bareQtPortNameIsDescribedLikeItsPath();
};

void TestDescribePort::ftdiAdapterIsDescribedFromSysfs() {
    ScratchTree tree;
    tree.addUsbSerial(QStringLiteral("ttyUSB0"), QStringLiteral("ftdi_sio"), kFt232r, 16);
    QVERIFY(tree.isValid());
    const SerialPortEntry entry =
        describePort(tree.dev(QStringLiteral("ttyUSB0")), tree.sys(), tree.byId());
    QCOMPARE(entry.portName, QStringLiteral("ttyUSB0"));
    QCOMPARE(entry.systemLocation,
             QFileInfo(tree.dev(QStringLiteral("ttyUSB0"))).canonicalFilePath());
    QCOMPARE(entry.driver, QStringLiteral("ftdi_sio"));
    QCOMPARE(entry.latencyTimerMs, std::optional<int>(16));
    QCOMPARE(entry.vendorId, std::optional<quint16>(0x0403));
    QCOMPARE(entry.productId, std::optional<quint16>(0x6001));
    QCOMPARE(entry.manufacturer, QStringLiteral("FTDI"));
    QCOMPARE(entry.description, QStringLiteral("FT232R USB UART"));
    QCOMPARE(entry.serialNumber, QStringLiteral("A10K1234"));
    QVERIFY(entry.byIdPath.isEmpty());
    QVERIFY(entry.isFtdi());
}

void TestDescribePort::displayNameShowsDescriptionManufacturerAndIds() {
    ScratchTree tree;
    tree.addUsbSerial(QStringLiteral("ttyUSB0"), QStringLiteral("ftdi_sio"), kFt232r, 1);
    QVERIFY(tree.isValid());
    const SerialPortEntry entry =
        describePort(tree.dev(QStringLiteral("ttyUSB0")), tree.sys(), tree.byId());
    QCOMPARE(entry.displayName(),
             QStringLiteral("ttyUSB0 %1 FT232R USB UART (FTDI 0403:6001)").arg(kEmDash));
}

void TestDescribePort::ftdiAdapterWithDefaultLatencyGetsAdvice_data() {
    QTest::addColumn<QString>("tty");
    QTest::addColumn<int>("latencyMs");
    QTest::newRow("ttyUSB0 at the kernel default") << QStringLiteral("ttyUSB0") << 16;
    QTest::newRow("ttyUSB3 at 2 ms") << QStringLiteral("ttyUSB3") << 2;
}

void TestDescribePort::ftdiAdapterWithDefaultLatencyGetsAdvice() {
    QFETCH(QString, tty);
    QFETCH(int, latencyMs);
    ScratchTree tree;
    tree.addUsbSerial(tty, QStringLiteral("ftdi_sio"), kFt232r, latencyMs);
    QVERIFY(tree.isValid());
    const QString advice = describePort(tree.dev(tty), tree.sys(), tree.byId()).latencyAdvice();
    QVERIFY2(advice.contains(QStringLiteral("%1 ms latency timer").arg(latencyMs)),
             qPrintable(advice));
    QVERIFY2(advice.contains(QStringLiteral("kernel default is 16 ms")), qPrintable(advice));
    QVERIFY2(advice.contains(
                 QStringLiteral("echo 1 | sudo tee /sys/bus/usb-serial/devices/%1/latency_timer")
                     .arg(tty)),
             qPrintable(advice));
    QVERIFY2(advice.contains(
                 QStringLiteral("ACTION==\"add\", SUBSYSTEM==\"usb-serial\", DRIVER==\"ftdi_sio\", "
                                "ATTR{latency_timer}=\"1\"")),
             qPrintable(advice));
    QVERIFY2(advice.contains(QStringLiteral("/etc/udev/rules.d/")), qPrintable(advice));
}

void TestDescribePort::ftdiAdapterAtOneMillisecondGetsNoAdvice() {
    ScratchTree tree;
    tree.addUsbSerial(QStringLiteral("ttyUSB0"), QStringLiteral("ftdi_sio"), kFt232r, 1);
    QVERIFY(tree.isValid());
    const SerialPortEntry entry =
        describePort(tree.dev(QStringLiteral("ttyUSB0")), tree.sys(), tree.byId());
    QCOMPARE(entry.latencyTimerMs, std::optional<int>(1));
    QCOMPARE(entry.latencyAdvice(), QString());
}

void TestDescribePort::otherUsbAdaptersHaveNoLatencyAndNoAdvice_data() {
    QTest::addColumn<QString>("driver");
    QTest::addColumn<QString>("ids");
    QTest::newRow("cp210x") << QStringLiteral("cp210x")
                            << QStringLiteral("10c4:ea60 Silicon Labs/CP2102 USB to UART Bridge "
                                              "Controller/0001");
    QTest::newRow("pl2303") << QStringLiteral("pl2303")
                            << QStringLiteral("067b:2303 Prolific Technology Inc./USB-Serial "
                                              "Controller/");
}

void TestDescribePort::otherUsbAdaptersHaveNoLatencyAndNoAdvice() {
    QFETCH(QString, driver);
    QFETCH(QString, ids);
    ScratchTree tree;
    tree.addUsbSerial(QStringLiteral("ttyUSB0"), driver, ids);
    QVERIFY(tree.isValid());
    const SerialPortEntry entry =
        describePort(tree.dev(QStringLiteral("ttyUSB0")), tree.sys(), tree.byId());
    QCOMPARE(entry.driver, driver);
    QCOMPARE(entry.vendorId, std::optional<quint16>(ids.left(4).toUShort(nullptr, 16)));
    QVERIFY(!entry.latencyTimerMs);
    QVERIFY(!entry.isFtdi());
    QCOMPARE(entry.latencyAdvice(), QString());
}

void TestDescribePort::acmDeviceGetsItsDriverFromTheInterface() {
    ScratchTree tree;
    tree.addAcm(QStringLiteral("ttyACM0"),
                QStringLiteral("2341:0043 Arduino (www.arduino.cc)/Uno/"));
    QVERIFY(tree.isValid());
    const SerialPortEntry entry =
        describePort(tree.dev(QStringLiteral("ttyACM0")), tree.sys(), tree.byId());
    QCOMPARE(entry.driver, QStringLiteral("cdc_acm"));
    QCOMPARE(entry.productId, std::optional<quint16>(0x0043));
    QCOMPARE(entry.displayName(),
             QStringLiteral("ttyACM0 %1 Uno (Arduino (www.arduino.cc) 2341:0043)").arg(kEmDash));
}

void TestDescribePort::plainRs232PortIsListedWithoutVidPid() {
    ScratchTree tree;
    tree.addPlatformUart(QStringLiteral("ttyS0"));
    QVERIFY(tree.isValid());
    const SerialPortEntry entry =
        describePort(tree.dev(QStringLiteral("ttyS0")), tree.sys(), tree.byId());
    QCOMPARE(entry.portName, QStringLiteral("ttyS0"));
    QCOMPARE(entry.driver, QStringLiteral("serial8250"));
    QVERIFY(!entry.vendorId);
    QVERIFY(!entry.productId);
    QCOMPARE(entry.displayName(), QStringLiteral("ttyS0 (serial8250)"));
    QCOMPARE(entry.latencyAdvice(), QString());
}

void TestDescribePort::uartBehindSerialBaseReportsTheHardwareDriver() {
    ScratchTree tree;
    tree.addUartBehindSerialBase(QStringLiteral("ttyS0"));
    QVERIFY(tree.isValid());
    const SerialPortEntry entry =
        describePort(tree.dev(QStringLiteral("ttyS0")), tree.sys(), tree.byId());
    QCOMPARE(entry.driver, QStringLiteral("serial"));
}

void TestDescribePort::byIdLinkBelongsOnlyToItsOwnPort() {
    ScratchTree tree;
    tree.addUsbSerial(QStringLiteral("ttyUSB0"), QStringLiteral("ftdi_sio"), kFt232r, 16);
    tree.addUsbSerial(QStringLiteral("ttyUSB1"), QStringLiteral("ftdi_sio"),
                      QStringLiteral("0403:6015 FTDI/FT231X USB UART/DN05XYZ"), 16);
    const QString link = tree.addByIdLink(
        QStringLiteral("usb-FTDI_FT231X_USB_UART_DN05XYZ-if00-port0"), QStringLiteral("ttyUSB1"));
    QVERIFY(tree.isValid());
    QCOMPARE(describePort(tree.dev(QStringLiteral("ttyUSB1")), tree.sys(), tree.byId()).byIdPath,
             link);
    QCOMPARE(describePort(tree.dev(QStringLiteral("ttyUSB0")), tree.sys(), tree.byId()).byIdPath,
             QString());
}

void TestDescribePort::typedByIdPathDescribesTheAdapterBehindIt() {
    ScratchTree tree;
    tree.addUsbSerial(QStringLiteral("ttyUSB0"), QStringLiteral("ftdi_sio"), kFt232r, 16);
    const QString link = tree.addByIdLink(
        QStringLiteral("usb-FTDI_FT232R_USB_UART_A10K1234-if00-port0"), QStringLiteral("ttyUSB0"));
    QVERIFY(tree.isValid());
    const SerialPortEntry entry = describePort(link, tree.sys(), tree.byId());
    QCOMPARE(entry.portName, QStringLiteral("ttyUSB0"));
    QCOMPARE(entry.systemLocation,
             QFileInfo(tree.dev(QStringLiteral("ttyUSB0"))).canonicalFilePath());
    QCOMPARE(entry.byIdPath, link);
    QCOMPARE(entry.driver, QStringLiteral("ftdi_sio"));
    QVERIFY(!entry.latencyAdvice().isEmpty());
}

void TestDescribePort::realPtyIsDescribedWithoutHardwareDetails() {
    ScratchPty pty;
    if (pty.slavePath().isEmpty())
        QSKIP("this system cannot create a pseudo terminal");
    const SerialPortEntry entry = describePort(pty.slavePath());
    QCOMPARE(entry.systemLocation, pty.slavePath());
    QCOMPARE(entry.portName, pty.slavePath().mid(int(qstrlen("/dev/"))));
    QVERIFY(entry.portName.startsWith(QStringLiteral("pts/")));
    QCOMPARE(entry.driver, QString());
    QVERIFY(!entry.vendorId);
    QCOMPARE(entry.byIdPath, QString());
    QCOMPARE(entry.displayName(), entry.portName);
}

void TestDescribePort::bareQtPortNameIsDescribedLikeItsPath() {
    ScratchPty pty;
    if (pty.slavePath().isEmpty())
        QSKIP("this system cannot create a pseudo terminal");
    const QString bareName = QSerialPort(pty.slavePath()).portName(); // "pts/N"
    QVERIFY2(!bareName.startsWith(QLatin1Char('/')), qPrintable(bareName));
    const SerialPortEntry entry = describePort(bareName);
    QCOMPARE(entry.systemLocation, pty.slavePath());
    QCOMPARE(entry.portName, bareName);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestDescribePort)

} // namespace tst_describeport
#include "tst_describeport.moc"
