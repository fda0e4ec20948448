// ScratchTree: the sysfs and /dev files of a machine with serial adapters plugged in, built in a
// temporary folder, for describePort() tests. No real FTDI adapter can exist in a container, so
// the tree copies what the kernel makes, including its relative links: /sys/class/tty/<tty> ->
// <device>/tty/<tty>, whose `device` link points back at the usb-serial port, USB interface or
// platform device; a `driver` link on that device; the USB ids two levels up; latency_timer on
// FTDI ports only; /dev/serial/by-id links of the form ../../ttyUSB0. Device nodes are plain files.
#pragma once

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <QTemporaryDir>
#include <optional>

#include <unistd.h>

class ScratchTree {
public:
    [[nodiscard]] bool isValid() const { return m_dir.isValid() && m_ok; }
    [[nodiscard]] QString sys() const { return path(QStringLiteral("sys")); }
    [[nodiscard]] QString byId() const { return path(QStringLiteral("dev/serial/by-id")); }
    [[nodiscard]] QString dev(const QString &tty) const {
        return path(QStringLiteral("dev/") + tty);
    }

    // A usb-serial adapter (ftdi_sio, cp210x, pl2303): the tty's device is the usb-serial port
    // below the USB interface, and only ftdi_sio gives that port a latency_timer.
    void addUsbSerial(const QString &tty, const QString &driver, const QString &ids,
                      std::optional<int> latencyMs = {}) {
        const QString port = addUsbDevice(ids) + QStringLiteral("/1-%1:1.0/").arg(m_usb) + tty;
        addTty(tty, port);
        link(QStringLiteral("../../../") + tty, port + QStringLiteral("/tty/") + tty + "/device");
        link(driverDir(QStringLiteral("usb-serial"), driver), port + QStringLiteral("/driver"));
        link(port, sys() + QStringLiteral("/bus/usb-serial/devices/") + tty);
        if (latencyMs)
            write(port + QStringLiteral("/latency_timer"), QByteArray::number(*latencyMs) + '\n');
    }

    // A CDC-ACM device: the tty's device is the USB interface itself.
    void addAcm(const QString &tty, const QString &ids) {
        const QString interface = addUsbDevice(ids) + QStringLiteral("/1-%1:1.0").arg(m_usb);
        addTty(tty, interface);
        link(QStringLiteral("../.."), interface + QStringLiteral("/tty/") + tty + "/device");
        link(driverDir(QStringLiteral("usb"), QStringLiteral("cdc_acm")),
             interface + QStringLiteral("/driver"));
    }

    // A UART as Linux 6.5+ shows it: tty -> serial-base port -> controller -> the pnp device
    // whose driver ("serial") is the one that matters.
    void addUartBehindSerialBase(const QString &tty) {
        const QString hw = sys() + QStringLiteral("/devices/pnp0/00:00");
        const QString ctrl = hw + QStringLiteral("/00:00:0");
        const QString port = ctrl + QStringLiteral("/00:00:0.0");
        addTty(tty, port);
        link(QStringLiteral("../../../00:00:0.0"),
             port + QStringLiteral("/tty/") + tty + "/device");
        const QString serialBase = sys() + QStringLiteral("/bus/serial-base");
        mkdir(serialBase);
        link(serialBase, port + QStringLiteral("/subsystem"));
        link(serialBase, ctrl + QStringLiteral("/subsystem"));
        link(driverDir(QStringLiteral("serial-base"), QStringLiteral("port")), port + "/driver");
        link(driverDir(QStringLiteral("serial-base"), QStringLiteral("ctrl")), ctrl + "/driver");
        link(driverDir(QStringLiteral("pnp"), QStringLiteral("serial")), hw + "/driver");
    }

    // A built-in UART on a kernel before 6.5: the tty's device is the platform device.
    void addPlatformUart(const QString &tty) {
        const QString hw = sys() + QStringLiteral("/devices/platform/serial8250");
        addTty(tty, hw);
        link(QStringLiteral("../../../serial8250"), hw + QStringLiteral("/tty/") + tty + "/device");
        link(driverDir(QStringLiteral("platform"), QStringLiteral("serial8250")), hw + "/driver");
    }

    // The relative link udev makes: /dev/serial/by-id/<name> -> ../../ttyUSB0.
    QString addByIdLink(const QString &name, const QString &tty) {
        mkdir(byId());
        link(QStringLiteral("../../") + tty, byId() + QLatin1Char('/') + name);
        return byId() + QLatin1Char('/') + name;
    }

private:
    [[nodiscard]] QString path(const QString &relative) const {
        return m_dir.path() + QLatin1Char('/') + relative;
    }

    // ids: "0403:6001 FTDI/FT232R USB UART/A10K1234" (vendor:product manufacturer/product/serial)
    QString addUsbDevice(const QString &ids) {
        const QString usb =
            sys() + QStringLiteral("/devices/pci0000:00/0000:00:14.0/usb1/1-%1").arg(++m_usb);
        const QStringList parts = ids.section(QLatin1Char(' '), 1).split(QLatin1Char('/'));
        write(usb + QStringLiteral("/idVendor"), ids.left(4).toLatin1() + '\n');
        write(usb + QStringLiteral("/idProduct"), ids.mid(5, 4).toLatin1() + '\n');
        write(usb + QStringLiteral("/manufacturer"), parts.value(0).toUtf8() + '\n');
        write(usb + QStringLiteral("/product"), parts.value(1).toUtf8() + '\n');
        write(usb + QStringLiteral("/serial"), parts.value(2).toUtf8() + '\n');
        return usb;
    }

    // /sys/class/tty/<tty> -> <device>/tty/<tty>, and the /dev node (a plain file will do).
    void addTty(const QString &tty, const QString &device) {
        mkdir(device + QStringLiteral("/tty/") + tty);
        mkdir(sys() + QStringLiteral("/class/tty"));
        link(device + QStringLiteral("/tty/") + tty, sys() + QStringLiteral("/class/tty/") + tty);
        write(dev(tty), {});
    }

    QString driverDir(const QString &bus, const QString &driver) {
        const QString dir = sys() + QStringLiteral("/bus/%1/drivers/%2").arg(bus, driver);
        mkdir(dir);
        return dir;
    }

    void mkdir(const QString &dir) { m_ok = m_ok && QDir().mkpath(dir); }
    void link(const QString &target, const QString &linkPath) {
        mkdir(QFileInfo(linkPath).path());
        m_ok = m_ok && ::symlink(QFile::encodeName(target).constData(),
                                 QFile::encodeName(linkPath).constData()) == 0;
    }
    void write(const QString &file, const QByteArray &content) {
        mkdir(QFileInfo(file).path());
        QFile out(file);
        m_ok = m_ok && out.open(QIODevice::WriteOnly) && out.write(content) == content.size();
    }

    QTemporaryDir m_dir;
    bool m_ok = true;
    int m_usb = 0;
};
