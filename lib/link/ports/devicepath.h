// How a name a user or QSerialPort gives maps to a device file.
//
// QSerialPort::portName() drops the "/dev/" of a device path ("ttyUSB0", "pts/3") but keeps
// other absolute or relative paths, so diagnostics receive either form. deviceLocation() undoes
// that with Qt's own rule; resolvedDevicePath() follows symbolic links (by-id, socat), so two
// names of one device compare equal. typedPortName() is for what a person types (tipscope-cli
// --port): Qt's rule would open "run/ttyX" as /dev/run/ttyX, where a person means a path.
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

namespace tipscope::link {

// A typed port name as QSerialPort must be given it: a name without a slash is a device in /dev
// ("ttyUSB0"); a name with one is a path, a relative one from the current folder ("run/ttyX" is
// ./run/ttyX, not /dev/run/ttyX).
inline QString typedPortName(const QString &typed) {
    if (!typed.contains(QLatin1Char('/')) || detail::deviceLocation(typed) == typed)
        return typed;
    return QStringLiteral("./") + typed;
}

} // namespace tipscope::link
