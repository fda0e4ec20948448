// SerialPortList: the serial ports on this machine, kept current, with the details that explain
// why a port behaves the way it does.
//
// Each entry joins what QSerialPortInfo reports with what only sysfs knows: the kernel driver, the
// FTDI latency timer (16 ms by default, which slows every request/answer exchange) and the
// stable /dev/serial/by-id name. Nothing is scanned until start() or refresh(). After start() the
// list rescans when the device folder (/dev, and the by-id folder once it exists) changes, which
// is when a port comes or goes, and otherwise every pollInterval() ms (30 s), for details such
// as a latency timer changed in sysfs. Listing the ports opens and stats hundreds of files, so
// the quiet machine is not scanned every second. changed() is emitted only when the set of ports or
// any detail of one differs from the previous scan; the order in which the system lists them does
// not count. The sysfs root and the by-id folder are constructor parameters so tests can point
// them at a scratch tree; the list of ports itself comes from QSerialPortInfo, which tests
// replace by overriding scanPorts().
#pragma once

#include <QFileSystemWatcher>
#include <QList>
#include <QObject>
#include <QString>
#include <QTimer>
#include <optional>

namespace tipscope::link {

inline constexpr const char *kDefaultSysRoot = "/sys";
inline constexpr const char *kDefaultByIdDir = "/dev/serial/by-id";
inline constexpr const char *kDefaultDeviceDir = "/dev";

struct SerialPortEntry {
    QString portName;       // ttyUSB0, ttyS0, pts/3
    QString systemLocation; // the device file, with symbolic links resolved
    QString description;
    QString manufacturer;
    QString serialNumber;
    std::optional<quint16> vendorId;
    std::optional<quint16> productId;
    QString byIdPath;                  // /dev/serial/by-id/... link that points at this port
    QString driver;                    // kernel driver: ftdi_sio, cp210x, pl2303, serial8250
    std::optional<int> latencyTimerMs; // FTDI only: usb-serial latency_timer

    // One line for a port menu: "ttyUSB0 — FT232R USB UART (FTDI 0403:6001)".
    [[nodiscard]] QString displayName() const;
    // Empty unless this is an FTDI adapter whose latency timer is above 1 ms; otherwise what it
    // costs and the commands that fix it now and after the next plug-in.
    [[nodiscard]] QString latencyAdvice() const;
    [[nodiscard]] bool isFtdi() const;

    bool operator==(const SerialPortEntry &other) const;
    bool operator!=(const SerialPortEntry &other) const { return !(*this == other); }
};

// Describes any device path, including one QSerialPortInfo does not list (a PTY, a socat link), a
// /dev/serial/by-id link, or a bare name as QSerialPort::portName() gives it ("ttyUSB0" means
// /dev/ttyUSB0), filling whatever QSerialPortInfo and sysfs know about it.
[[nodiscard]] SerialPortEntry
describePort(const QString &systemLocation,
             const QString &sysRoot = QString::fromLatin1(kDefaultSysRoot),
             const QString &byIdDir = QString::fromLatin1(kDefaultByIdDir));

class SerialPortList : public QObject {
    Q_OBJECT
public:
    explicit SerialPortList(const QString &sysRoot = QString::fromLatin1(kDefaultSysRoot),
                            const QString &byIdDir = QString::fromLatin1(kDefaultByIdDir),
                            QObject *parent = nullptr);

    // Sorted by systemLocation.
    [[nodiscard]] QList<SerialPortEntry> ports() const { return m_ports; }
    [[nodiscard]] int pollInterval() const { return m_timer.interval(); }
    void setPollInterval(int ms) { m_timer.setInterval(ms); }
    [[nodiscard]] bool isPolling() const { return m_timer.isActive(); }
    [[nodiscard]] QString sysRoot() const { return m_sysRoot; }
    [[nodiscard]] QString byIdDir() const { return m_byIdDir; }
    // The folder whose changes trigger a rescan; set before start().
    void setDeviceDirectory(const QString &dir) { m_deviceDir = dir; }
    [[nodiscard]] QString deviceDirectory() const { return m_deviceDir; }

public Q_SLOTS:
    // Scans now and starts polling.
    void start();
    void stop();
    // Scans now; emits changed() if the result differs from the last scan.
    void refresh();

Q_SIGNALS:
    void changed();

protected:
    // The current ports, in any order. The default asks QSerialPortInfo and adds sysfs details;
    // tests override it because ports cannot be plugged in here.
    [[nodiscard]] virtual QList<SerialPortEntry> scanPorts() const;

private:
    void watchFolders();

    QString m_sysRoot;
    QString m_byIdDir;
    QString m_deviceDir = QString::fromLatin1(kDefaultDeviceDir);
    QTimer m_timer;
    // udev adds the device node, then its by-id link and permissions: one rescan after the burst.
    QTimer m_settle;
    QFileSystemWatcher m_watcher;
    QList<SerialPortEntry> m_ports;
};

} // namespace tipscope::link
