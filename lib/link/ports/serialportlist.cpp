#include "serialportlist.h"

#include "devicepath.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QSerialPortInfo>
#include <algorithm>

namespace tipscope::link {
namespace {

Q_LOGGING_CATEGORY(lcPorts, "tipscope.link.ports")

constexpr quint16 kFtdiVendorId = 0x0403;
// The USB device is at most two levels above the tty's device (usb-serial port -> interface ->
// device); looking further up would reach the hub the adapter is plugged into.
constexpr int kUsbAncestorLevels = 3;
// A UART tty sits below a serial-base port device and a controller device (Linux 6.5 and later).
constexpr int kSerialBaseLevels = 2;

// Same rule as QSerialPortInfo, so a PTY reads "pts/3" rather than "3".
QString portNameFor(const QString &resolved) {
    const QString dev = QStringLiteral("/dev/");
    return resolved.startsWith(dev) ? resolved.mid(dev.size()) : QFileInfo(resolved).fileName();
}

QString readAttribute(const QString &path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll()).trimmed();
}

// The last component of where a sysfs link points, e.g. "ftdi_sio" for a driver link.
QString linkName(const QString &link) {
    return QFileInfo(QFileInfo(link).canonicalFilePath()).fileName();
}

// Since Linux 6.5 the drivers of the serial-base devices ("port", "ctrl") sit between a UART's
// tty and its hardware; they say nothing, so the driver is read from the device above them.
QString driverOf(QString deviceDir) {
    for (int level = 0; level < kSerialBaseLevels; ++level) {
        if (linkName(deviceDir + QStringLiteral("/subsystem")) != QLatin1String("serial-base"))
            break;
        deviceDir = QFileInfo(deviceDir).path();
    }
    return linkName(deviceDir + QStringLiteral("/driver"));
}

std::optional<quint16> readHexId(const QString &path) {
    bool ok = false;
    const quint16 id = readAttribute(path).toUShort(&ok, 16);
    return ok ? std::optional<quint16>(id) : std::nullopt;
}

QString findByIdLink(const QString &resolved, const QString &byIdDir) {
    const QFileInfoList links =
        QDir(byIdDir).entryInfoList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot);
    for (const QFileInfo &link : links) {
        if (link.isSymLink() && detail::resolvedDevicePath(link.absoluteFilePath()) == resolved)
            return link.absoluteFilePath();
    }
    return {};
}

void fillIfEmpty(QString &field, const QString &value) {
    if (field.isEmpty())
        field = value;
}

// QSerialPortInfo normally has these already; sysfs fills them for paths it does not list.
void addUsbDetails(SerialPortEntry &entry, QString dir) {
    for (int level = 0; level < kUsbAncestorLevels; ++level, dir = QFileInfo(dir).path()) {
        if (!QFileInfo::exists(dir + QStringLiteral("/idVendor")))
            continue;
        if (!entry.vendorId)
            entry.vendorId = readHexId(dir + QStringLiteral("/idVendor"));
        if (!entry.productId)
            entry.productId = readHexId(dir + QStringLiteral("/idProduct"));
        fillIfEmpty(entry.description, readAttribute(dir + QStringLiteral("/product")));
        fillIfEmpty(entry.manufacturer, readAttribute(dir + QStringLiteral("/manufacturer")));
        fillIfEmpty(entry.serialNumber, readAttribute(dir + QStringLiteral("/serial")));
        return;
    }
}

void addSysfsDetails(SerialPortEntry &entry, const QString &sysRoot) {
    const QString name = QFileInfo(entry.systemLocation).fileName();
    const QString deviceDir =
        QFileInfo(sysRoot + QStringLiteral("/class/tty/%1/device").arg(name)).canonicalFilePath();
    if (deviceDir.isEmpty())
        return; // PTYs and virtual consoles have no hardware behind them
    entry.driver = driverOf(deviceDir);
    bool ok = false;
    const int latency =
        readAttribute(sysRoot +
                      QStringLiteral("/bus/usb-serial/devices/%1/latency_timer").arg(name))
            .toInt(&ok);
    if (ok)
        entry.latencyTimerMs = latency;
    addUsbDetails(entry, deviceDir);
}

void completeEntry(SerialPortEntry &entry, const QString &sysRoot, const QString &byIdDir) {
    entry.byIdPath = findByIdLink(detail::resolvedDevicePath(entry.systemLocation), byIdDir);
    addSysfsDetails(entry, sysRoot);
}

SerialPortEntry entryFromInfo(const QSerialPortInfo &info, const QString &sysRoot,
                              const QString &byIdDir) {
    SerialPortEntry entry;
    entry.portName = info.portName();
    entry.systemLocation = info.systemLocation();
    entry.description = info.description();
    entry.manufacturer = info.manufacturer();
    entry.serialNumber = info.serialNumber();
    if (info.hasVendorIdentifier())
        entry.vendorId = info.vendorIdentifier();
    if (info.hasProductIdentifier())
        entry.productId = info.productIdentifier();
    completeEntry(entry, sysRoot, byIdDir);
    return entry;
}

QString hexId(quint16 id) {
    return QStringLiteral("%1").arg(id, 4, 16, QLatin1Char('0'));
}

} // namespace

QString SerialPortEntry::displayName() const {
    QString name = portName.isEmpty() ? systemLocation : portName;
    if (!description.isEmpty())
        name += QStringLiteral(" \u2014 ") + description;
    QStringList origin;
    if (!manufacturer.isEmpty())
        origin << manufacturer;
    if (vendorId && productId)
        origin << hexId(*vendorId) + QLatin1Char(':') + hexId(*productId);
    // A built-in RS-232 port has neither; its driver still tells it apart from a pseudo terminal.
    if (origin.isEmpty() && !driver.isEmpty())
        origin << driver;
    if (!origin.isEmpty())
        name += QStringLiteral(" (") + origin.join(QLatin1Char(' ')) + QLatin1Char(')');
    return name;
}

bool SerialPortEntry::isFtdi() const {
    return driver == QLatin1String("ftdi_sio") || vendorId == kFtdiVendorId;
}

QString SerialPortEntry::latencyAdvice() const {
    if (!isFtdi() || !latencyTimerMs || *latencyTimerMs <= 1)
        return {};
    // The FTDI chip holds received bytes until its buffer fills or the latency timer expires, so
    // each short answer waits the full timer: the station is polled far slower than it could be.
    return QCoreApplication::translate(
               "SerialPortList",
               "%1 is an FTDI adapter with a %2 ms latency timer (the kernel default is 16 ms), "
               "which holds back every short answer and throttles request/answer traffic.\n"
               "Set it to 1 ms now with:\n"
               "  echo 1 | sudo tee /sys/bus/usb-serial/devices/%1/latency_timer\n"
               "Make it permanent with this udev rule:\n"
               "  echo 'ACTION==\"add\", SUBSYSTEM==\"usb-serial\", DRIVER==\"ftdi_sio\", "
               "ATTR{latency_timer}=\"1\"' | sudo tee /etc/udev/rules.d/99-ftdi-latency.rules")
        .arg(portName)
        .arg(*latencyTimerMs);
}

bool SerialPortEntry::operator==(const SerialPortEntry &other) const {
    return portName == other.portName && systemLocation == other.systemLocation &&
           description == other.description && manufacturer == other.manufacturer &&
           serialNumber == other.serialNumber && vendorId == other.vendorId &&
           productId == other.productId && byIdPath == other.byIdPath && driver == other.driver &&
           latencyTimerMs == other.latencyTimerMs;
}

SerialPortEntry describePort(const QString &systemLocation, const QString &sysRoot,
                             const QString &byIdDir) {
    const QString resolved = detail::resolvedDevicePath(systemLocation);
    const QList<QSerialPortInfo> infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &info : infos) {
        if (detail::resolvedDevicePath(info.systemLocation()) == resolved)
            return entryFromInfo(info, sysRoot, byIdDir);
    }
    SerialPortEntry entry;
    entry.systemLocation = resolved;
    entry.portName = portNameFor(resolved);
    completeEntry(entry, sysRoot, byIdDir);
    return entry;
}

SerialPortList::SerialPortList(const QString &sysRoot, const QString &byIdDir, QObject *parent)
    : QObject(parent)
    , m_sysRoot(sysRoot)
    , m_byIdDir(byIdDir)
    , m_timer(this)
    , m_settle(this)
    , m_watcher(this) {
    m_timer.setInterval(30'000);
    connect(&m_timer, &QTimer::timeout, this, &SerialPortList::refresh);
    m_settle.setSingleShot(true);
    m_settle.setInterval(250);
    connect(&m_settle, &QTimer::timeout, this, &SerialPortList::refresh);
    connect(&m_watcher, &QFileSystemWatcher::directoryChanged, &m_settle,
            qOverload<>(&QTimer::start));
}

void SerialPortList::start() {
    m_timer.start();
    refresh();
}

void SerialPortList::stop() {
    m_timer.stop();
    m_settle.stop();
    if (!m_watcher.directories().isEmpty())
        m_watcher.removePaths(m_watcher.directories());
}

// The by-id folder exists only while a USB adapter is plugged in, and the watcher forgets a
// folder that is removed: both are (re)added after each scan.
void SerialPortList::watchFolders() {
    if (!m_timer.isActive())
        return;
    for (const QString &dir : {m_deviceDir, m_byIdDir})
        if (!m_watcher.directories().contains(dir) && QFileInfo(dir).isDir())
            m_watcher.addPath(dir);
}

void SerialPortList::refresh() {
    QList<SerialPortEntry> current = scanPorts();
    watchFolders();
    std::stable_sort(current.begin(), current.end(),
                     [](const SerialPortEntry &a, const SerialPortEntry &b) {
                         return a.systemLocation < b.systemLocation;
                     });
    if (current == m_ports)
        return;
    m_ports = std::move(current);
    qCDebug(lcPorts) << "serial ports changed, now" << m_ports.size();
    Q_EMIT changed();
}

QList<SerialPortEntry> SerialPortList::scanPorts() const {
    QList<SerialPortEntry> entries;
    const QList<QSerialPortInfo> infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &info : infos)
        entries.append(entryFromInfo(info, m_sysRoot, m_byIdDir));
    return entries;
}

} // namespace tipscope::link
