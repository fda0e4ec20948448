// Port diagnostics: turn a failed QSerialPort::open() into what a person should do next.
//
// explainOpenFailure() returns one or two plain sentences for the status bar or a dialog. A
// PermissionError is most often another program holding the port (QSerialPort takes an exclusive
// lock), so it first looks for that process and names it; only when none is found does it blame
// group membership and give the exact usermod command. A port may be given as a path or the way
// QSerialPort::portName() gives it ("ttyUSB0" means /dev/ttyUSB0); messages quote it as given.
// Both functions only read and need no privileges: fd folders of other users' processes that
// cannot be read are skipped. The /proc root is a parameter so tests can use a scratch tree.
#pragma once

#include <QList>
#include <QSerialPort>
#include <QString>

namespace tipscope::link {

inline constexpr const char *kDefaultProcRoot = "/proc";

// PIDs whose open file descriptors resolve to the same file as path (symbolic links such as
// /dev/serial/by-id or socat links resolved), in ascending order.
[[nodiscard]] QList<qint64>
processesHolding(const QString &path,
                 const QString &procRoot = QString::fromLatin1(kDefaultProcRoot));

// The short command name of a process ("minicom"), or empty if it is gone.
[[nodiscard]] QString processName(qint64 pid,
                                  const QString &procRoot = QString::fromLatin1(kDefaultProcRoot));

[[nodiscard]] QString
explainOpenFailure(const QString &systemLocation, QSerialPort::SerialPortError error,
                   const QString &qtErrorString,
                   const QString &procRoot = QString::fromLatin1(kDefaultProcRoot));

} // namespace tipscope::link
