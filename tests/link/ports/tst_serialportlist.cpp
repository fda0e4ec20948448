// SerialPortList: changed() fires when the set of ports or a detail of one differs, and never for
// a rescan that finds the same ports. Adapters cannot be plugged in here, so FakePortList replaces
// the QSerialPortInfo scan with a list the test edits.
#include "link/ports/serialportlist.h"
#include "testmain.h"

#include <QDir>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_serialportlist {

using namespace tipscope::link;

namespace {

class FakePortList : public SerialPortList {
public:
    using SerialPortList::SerialPortList;
    QList<SerialPortEntry> next;

protected:
    QList<SerialPortEntry> scanPorts() const override { return next; }
};

SerialPortEntry ftdiAdapter(const QString &name) {
    SerialPortEntry entry;
    entry.portName = name;
    entry.systemLocation = QStringLiteral("/dev/") + name;
    entry.description = QStringLiteral("FT232R USB UART");
    entry.manufacturer = QStringLiteral("FTDI");
    entry.serialNumber = QStringLiteral("A10K1234");
    entry.vendorId = 0x0403;
    entry.productId = 0x6001;
    entry.byIdPath =
        QStringLiteral("/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A10K1234-if00-port0");
    entry.driver = QStringLiteral("ftdi_sio");
    entry.latencyTimerMs = 16;
    return entry;
}

SerialPortEntry builtInPort(const QString &name) {
    SerialPortEntry entry;
    entry.portName = name;
    entry.systemLocation = QStringLiteral("/dev/") + name;
    entry.driver = QStringLiteral("serial8250");
    return entry;
}

} // namespace

} // namespace tst_serialportlist

namespace tipscope::link {
// Found by QCOMPARE through argument-dependent lookup, so a failure shows which port differed.
char *toString(const SerialPortEntry &entry) {
    return QTest::toString(entry.displayName() + QStringLiteral(" at ") + entry.systemLocation);
}
} // namespace tipscope::link

namespace tst_serialportlist {

class TestSerialPortList : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void pollIntervalDefaultsToThirtySeconds();
    void firstScanThatFindsPortsEmitsChanged();
    void firstScanThatFindsNothingStaysQuiet();
    void rescanFindingTheSamePortsDoesNotEmit();
    void pluggedInAdapterEmitsChangedOnce();
    void unpluggedAdapterEmitsChanged();
    void changedDetailEmitsChanged_data();
    void changedDetailEmitsChanged();
    void differentScanOrderIsNotAChange();
    void portsAreSortedBySystemLocation();
    void pollingPicksUpANewPortWithoutAnExplicitRefresh();
    void stoppedListNoLongerPolls();
    void newDeviceNodeIsPickedUpWithoutWaitingForThePoll();
    void stoppedListIgnoresTheDeviceFolder();
    void realScanDescribesBuiltInPortsWithTheirDriver();
};

void TestSerialPortList::pollIntervalDefaultsToThirtySeconds() {
    FakePortList list;
    QCOMPARE(list.pollInterval(), 30'000);
    QCOMPARE(list.deviceDirectory(), QStringLiteral("/dev"));
    QVERIFY(!list.isPolling());
    QCOMPARE(list.sysRoot(), QStringLiteral("/sys"));
    QCOMPARE(list.byIdDir(), QStringLiteral("/dev/serial/by-id"));
}

void TestSerialPortList::firstScanThatFindsPortsEmitsChanged() {
    FakePortList list;
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    list.next = {builtInPort(QStringLiteral("ttyS0"))};
    list.refresh();
    QCOMPARE(spy.count(), 1);
    QCOMPARE(list.ports().size(), 1);
    QCOMPARE(list.ports().first(), builtInPort(QStringLiteral("ttyS0")));
}

void TestSerialPortList::firstScanThatFindsNothingStaysQuiet() {
    FakePortList list;
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    list.refresh();
    QCOMPARE(spy.count(), 0);
    QVERIFY(list.ports().isEmpty());
}

void TestSerialPortList::rescanFindingTheSamePortsDoesNotEmit() {
    FakePortList list;
    list.next = {builtInPort(QStringLiteral("ttyS0")), ftdiAdapter(QStringLiteral("ttyUSB0"))};
    list.refresh();
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    list.refresh();
    list.refresh();
    QCOMPARE(spy.count(), 0);
}

void TestSerialPortList::pluggedInAdapterEmitsChangedOnce() {
    FakePortList list;
    list.next = {builtInPort(QStringLiteral("ttyS0"))};
    list.refresh();
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    list.next.append(ftdiAdapter(QStringLiteral("ttyUSB0")));
    list.refresh();
    list.refresh();
    QCOMPARE(spy.count(), 1);
    QCOMPARE(list.ports().size(), 2);
}

void TestSerialPortList::unpluggedAdapterEmitsChanged() {
    FakePortList list;
    list.next = {builtInPort(QStringLiteral("ttyS0")), ftdiAdapter(QStringLiteral("ttyUSB0"))};
    list.refresh();
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    list.next.removeLast();
    list.refresh();
    QCOMPARE(spy.count(), 1);
    QCOMPARE(list.ports(), QList<SerialPortEntry>{builtInPort(QStringLiteral("ttyS0"))});
}

void TestSerialPortList::changedDetailEmitsChanged_data() {
    QTest::addColumn<QString>("field");
    for (const char *field :
         {"portName", "systemLocation", "description", "manufacturer", "serialNumber", "vendorId",
          "productId", "byIdPath", "driver", "latencyTimerMs"})
        QTest::newRow(field) << QString::fromLatin1(field);
}

void TestSerialPortList::changedDetailEmitsChanged() {
    QFETCH(QString, field);
    FakePortList list;
    list.next = {ftdiAdapter(QStringLiteral("ttyUSB0"))};
    list.refresh();
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());

    SerialPortEntry &entry = list.next.first();
    const QString changed = QStringLiteral("changed");
    if (field == QLatin1String("portName"))
        entry.portName = changed;
    else if (field == QLatin1String("systemLocation"))
        entry.systemLocation = changed;
    else if (field == QLatin1String("description"))
        entry.description = changed;
    else if (field == QLatin1String("manufacturer"))
        entry.manufacturer = changed;
    else if (field == QLatin1String("serialNumber"))
        entry.serialNumber = changed;
    else if (field == QLatin1String("vendorId"))
        entry.vendorId.reset();
    else if (field == QLatin1String("productId"))
        entry.productId = 0x6015;
    else if (field == QLatin1String("byIdPath"))
        entry.byIdPath.clear();
    else if (field == QLatin1String("driver"))
        entry.driver = QStringLiteral("usbserial_generic");
    else // the user applied the latency advice
        entry.latencyTimerMs = 1;

    list.refresh();
    QCOMPARE(spy.count(), 1);
    QCOMPARE(list.ports().first(), list.next.first());
}

void TestSerialPortList::differentScanOrderIsNotAChange() {
    FakePortList list;
    list.next = {ftdiAdapter(QStringLiteral("ttyUSB0")), builtInPort(QStringLiteral("ttyS0"))};
    list.refresh();
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    std::reverse(list.next.begin(), list.next.end());
    list.refresh();
    QCOMPARE(spy.count(), 0);
}

void TestSerialPortList::portsAreSortedBySystemLocation() {
    FakePortList list;
    list.next = {ftdiAdapter(QStringLiteral("ttyUSB1")), builtInPort(QStringLiteral("ttyS0")),
                 ftdiAdapter(QStringLiteral("ttyUSB0"))};
    list.refresh();
    QStringList locations;
    for (const SerialPortEntry &entry : list.ports())
        locations << entry.systemLocation;
    QCOMPARE(locations, (QStringList{QStringLiteral("/dev/ttyS0"), QStringLiteral("/dev/ttyUSB0"),
                                     QStringLiteral("/dev/ttyUSB1")}));
}

void TestSerialPortList::pollingPicksUpANewPortWithoutAnExplicitRefresh() {
    FakePortList list;
    list.setPollInterval(20);
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    list.start();
    QVERIFY(list.isPolling());
    QCOMPARE(spy.count(), 0);

    list.next = {ftdiAdapter(QStringLiteral("ttyUSB0"))};
    QTRY_COMPARE_WITH_TIMEOUT(spy.count(), 1, 2000);
    QTest::qWait(100); // several more polls of an unchanged list
    QCOMPARE(spy.count(), 1);
}

void TestSerialPortList::stoppedListNoLongerPolls() {
    FakePortList list;
    list.setPollInterval(20);
    list.start();
    list.stop();
    QVERIFY(!list.isPolling());
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    list.next = {ftdiAdapter(QStringLiteral("ttyUSB0"))};
    QTest::qWait(150);
    QCOMPARE(spy.count(), 0);
}

// A device node appearing in the watched folder (here a scratch folder standing in for /dev)
// rescans at once; the poll alone would take a minute.
void TestSerialPortList::newDeviceNodeIsPickedUpWithoutWaitingForThePoll() {
    QTemporaryDir dev;
    QVERIFY(dev.isValid());
    FakePortList list(QStringLiteral("/sys"), dev.filePath(QStringLiteral("serial/by-id")));
    list.setPollInterval(60'000);
    list.setDeviceDirectory(dev.path());
    QSignalSpy spy(&list, &SerialPortList::changed);
    QVERIFY(spy.isValid());
    list.start();
    QTest::qWait(50);
    list.next = {ftdiAdapter(QStringLiteral("ttyUSB0"))};
    QFile node(dev.filePath(QStringLiteral("ttyUSB0")));
    QVERIFY(node.open(QIODevice::WriteOnly));
    node.close();
    QTRY_COMPARE_WITH_TIMEOUT(spy.count(), 1, 5000);
    QCOMPARE(list.ports().value(0).portName, QStringLiteral("ttyUSB0"));

    // Its by-id folder appears with the adapter and is watched from the next scan on.
    QVERIFY(QDir(dev.path()).mkpath(QStringLiteral("serial/by-id")));
    QTest::qWait(600); // its rescan (250 ms after the change) finds the same ports
    QCOMPARE(spy.count(), 1);
    list.next.first().latencyTimerMs = 1;
    QFile link(dev.filePath(QStringLiteral("serial/by-id/usb-FTDI")));
    QVERIFY(link.open(QIODevice::WriteOnly));
    link.close();
    QTRY_COMPARE_WITH_TIMEOUT(spy.count(), 2, 5000);
}

void TestSerialPortList::stoppedListIgnoresTheDeviceFolder() {
    QTemporaryDir dev;
    QVERIFY(dev.isValid());
    FakePortList list;
    list.setPollInterval(60'000);
    list.setDeviceDirectory(dev.path());
    list.start();
    list.stop();
    QSignalSpy spy(&list, &SerialPortList::changed);
    list.next = {ftdiAdapter(QStringLiteral("ttyUSB0"))};
    QFile node(dev.filePath(QStringLiteral("ttyUSB0")));
    QVERIFY(node.open(QIODevice::WriteOnly));
    node.close();
    QTest::qWait(600);
    QCOMPARE(spy.count(), 0);
}

void TestSerialPortList::realScanDescribesBuiltInPortsWithTheirDriver() {
    SerialPortList list;
    list.refresh();
    if (list.ports().isEmpty())
        QSKIP("QSerialPortInfo lists no serial port on this machine");
    for (const SerialPortEntry &entry : list.ports()) {
        QVERIFY2(!entry.portName.isEmpty(), qPrintable(entry.systemLocation));
        QVERIFY2(entry.displayName().startsWith(entry.portName), qPrintable(entry.displayName()));
        const QString sysDevice = QStringLiteral("/sys/class/tty/%1/device").arg(entry.portName);
        if (!QFileInfo::exists(sysDevice))
            continue;
        // serial-base's "port" driver would mean the real driver was not looked up.
        QVERIFY2(!entry.driver.isEmpty() && entry.driver != QLatin1String("port"),
                 qPrintable(entry.portName + QStringLiteral(": ") + entry.driver));
    }
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSerialPortList)

} // namespace tst_serialportlist
#include "tst_serialportlist.moc"
