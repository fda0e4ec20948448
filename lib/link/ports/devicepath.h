// Internal to tipscope_ports: how a name a user or QSerialPort gives maps to a device file.
//
// QSerialPort::portName() drops the "/dev/" of a device path ("ttyUSB0", "pts/3") but keeps
// other absolute or relative paths, so diagnostics receive either form. deviceLocation() undoes
// that with Qt's own rule; resolvedDevicePath() follows symbolic links (by-id, socat), so two
// names of one device compare equal.
#pragma once

#include <QDir>
#include <QFileInfo>
#include <QString>

namespace tipscope::link::detail {

inline QString deviceLocation(const QString &name) {
    if (name.isEmpty() || name.startsWith(QLatin1Char('/')) ||
        name.startsWith(QLatin1String("./")) || name.startsWith(QLatin1String("../")))
        return name;
    return QStringLiteral("/dev/") + name;
}

// A path that does not exist is only cleaned, so that it still compares equal to itself.
inline QString resolvedDevicePath(const QString &name) {
    const QFileInfo info(deviceLocation(name));
    const QString canonical = info.canonicalFilePath();
    return canonical.isEmpty() ? QDir::cleanPath(info.absoluteFilePath()) : canonical;
}

} // namespace tipscope::link::detail
