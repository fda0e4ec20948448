#include "portdiagnostics.h"

#include "devicepath.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <algorithm>

namespace tipscope::link {
namespace {

struct PortDiagnosticsTr {
    Q_DECLARE_TR_FUNCTIONS(PortDiagnostics)
};

const QString kDialout = QStringLiteral("dialout");
// What a file name and a path may hold (NAME_MAX, PATH_MAX); a lock file adds a few bytes.
constexpr qsizetype kMaxPortNameBytes = 240;
constexpr qsizetype kMaxPortPathChars = 4000;

bool processHolds(const QString &fdDir, const QString &target) {
    // /proc/<pid>/fd/* are symbolic links; sockets and pipes point nowhere and are listed only
    // with QDir::System. An unreadable folder simply lists nothing.
    const QFileInfoList fds =
        QDir(fdDir).entryInfoList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot);
    return std::any_of(fds.cbegin(), fds.cend(), [&target](const QFileInfo &fd) {
        return fd.isSymLink() && fd.symLinkTarget() == target;
    });
}

QString holderList(const QList<qint64> &pids, const QString &procRoot) {
    QStringList holders;
    for (const qint64 pid : pids) {
        QString name = processName(pid, procRoot);
        // A second connection in this very program: "close that program" alone would mislead.
        if (pid == QCoreApplication::applicationPid())
            name += name.isEmpty() ? PortDiagnosticsTr::tr("this program")
                                   : PortDiagnosticsTr::tr(", this program");
        holders << (name.isEmpty() ? QStringLiteral("PID %1").arg(pid)
                                   : QStringLiteral("PID %1 (%2)").arg(pid).arg(name));
    }
    return holders.join(QStringLiteral(", "));
}

QString explainNoAccess(const QString &systemLocation) {
    const QString group = QFileInfo(detail::deviceLocation(systemLocation)).group();
    const QString fix =
        PortDiagnosticsTr::tr("run `sudo usermod -aG %1 $USER`, then log out and back in.");
    if (group.isEmpty() || group == kDialout)
        return PortDiagnosticsTr::tr("You are not allowed to open %1: %2")
            .arg(systemLocation, fix.arg(kDialout));
    if (group == QLatin1String("root"))
        return PortDiagnosticsTr::tr(
                   "You are not allowed to open %1, and it belongs to group root rather than "
                   "dialout, so joining a group will not help until a udev rule gives it "
                   "GROUP=\"dialout\". Then %2")
            .arg(systemLocation, fix.arg(kDialout));
    return PortDiagnosticsTr::tr(
               "You are not allowed to open %1, which belongs to group %2 (not dialout): %3")
        .arg(systemLocation, group, fix.arg(group));
}

QString withQtReason(const QString &sentence, const QString &qtErrorString) {
    if (qtErrorString.isEmpty())
        return sentence + QLatin1Char('.');
    return sentence + QStringLiteral(" (%1).").arg(qtErrorString);
}

} // namespace

QList<qint64> processesHolding(const QString &path, const QString &procRoot) {
    const QString target = detail::resolvedDevicePath(path);
    QList<qint64> pids;
    const QStringList entries = QDir(procRoot).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString &entry : entries) {
        bool isPid = false;
        const qint64 pid = entry.toLongLong(&isPid);
        if (isPid &&
            processHolds(procRoot + QLatin1Char('/') + entry + QStringLiteral("/fd"), target))
            pids << pid;
    }
    std::sort(pids.begin(), pids.end());
    return pids;
}

QString processName(qint64 pid, const QString &procRoot) {
    QFile comm(QStringLiteral("%1/%2/comm").arg(procRoot).arg(pid));
    if (!comm.open(QIODevice::ReadOnly))
        return {};
    return QString::fromLocal8Bit(comm.readAll()).trimmed();
}

QString explainOpenFailure(const QString &systemLocation, QSerialPort::SerialPortError error,
                           const QString &qtErrorString, const QString &procRoot) {
    // No port has such a name, and its lock file cannot have one either, which QSerialPort
    // reports as a PermissionError: said as what it is, not as a group to join.
    if (const qsizetype bytes = QFile::encodeName(QFileInfo(systemLocation).fileName()).size();
        bytes > kMaxPortNameBytes || systemLocation.size() > kMaxPortPathChars)
        return PortDiagnosticsTr::tr("There is no such port in %1: a port's name is never %2 "
                                     "characters long. The port name may be mistyped.")
            .arg(QFileInfo(systemLocation).path().left(160))
            .arg(bytes > kMaxPortNameBytes ? bytes : systemLocation.size());
    switch (error) {
    case QSerialPort::PermissionError: {
        // QSerialPort locks the port, so a port held elsewhere also reports PermissionError;
        // telling the user to change groups then would send them the wrong way.
        const QList<qint64> holders = processesHolding(systemLocation, procRoot);
        if (!holders.isEmpty())
            return PortDiagnosticsTr::tr(
                       "%1 is busy: it is held by %2. Close that connection, then try again.")
                .arg(systemLocation, holderList(holders, procRoot));
        return explainNoAccess(systemLocation);
    }
    case QSerialPort::DeviceNotFoundError:
        return PortDiagnosticsTr::tr(
                   "There is no such port: %1. The adapter may be unplugged, or the port name "
                   "may be mistyped.")
            .arg(systemLocation);
    case QSerialPort::OpenError:
        return withQtReason(
            PortDiagnosticsTr::tr("%1 is already open in TipScope; close that connection first")
                .arg(systemLocation),
            qtErrorString);
    case QSerialPort::ResourceError:
        return withQtReason(
            PortDiagnosticsTr::tr("%1 stopped working, perhaps because the adapter was unplugged")
                .arg(systemLocation),
            qtErrorString);
    default:
        return withQtReason(PortDiagnosticsTr::tr("Could not open %1").arg(systemLocation),
                            qtErrorString);
    }
}

} // namespace tipscope::link
