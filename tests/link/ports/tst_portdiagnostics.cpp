// processesHolding() and explainOpenFailure(): a port held by another process is found and named
// for real (a PTY whose slave a child `sleep` holds open), the group advice follows the group
// that owns the device file, and every other error says what happened in a person's words.
#include "link/ports/portdiagnostics.h"
#include "scratchpty.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QSerialPort>
#include <QTemporaryDir>
#include <QTest>

#include <grp.h>
#include <unistd.h>

namespace tst_portdiagnostics {

using namespace tipscope::link;

class TestPortDiagnostics : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void childHoldingAPtyIsFound();
    void linkToAHeldPtyFindsTheSameHolder();
    void ptyNobodyOpenedHasNoHolder();
    void bareQtPortNameOfAHeldPtyFindsTheChild();
    void scratchProcTreeIsReadPidByPid();
    void permissionErrorOnAHeldPortNamesTheHolder();
    void secondOpenInThisProgramIsExplainedAsSuch();
    void permissionErrorWithoutHolderGivesTheGroupFix_data();
    void permissionErrorWithoutHolderGivesTheGroupFix();
    void missingPortSaysNoSuchPort();
    void anOverLongPortNameIsNoPortNotAGroupProblem();
    void otherErrorsQuoteQtsReason_data();
    void otherErrorsQuoteQtsReason();
};

void TestPortDiagnostics::childHoldingAPtyIsFound() {
    ScratchPty pty;
    if (pty.slavePath().isEmpty())
        QSKIP("this system cannot create a pseudo terminal");
    const qint64 pid = pty.holdInChild();
    QVERIFY(pid > 0);
    QTRY_VERIFY_WITH_TIMEOUT(processesHolding(pty.slavePath()).contains(pid), 5000);
    QTRY_COMPARE_WITH_TIMEOUT(processName(pid), QStringLiteral("sleep"), 5000);
    // This test process holds only the master side, never the slave.
    QVERIFY(!processesHolding(pty.slavePath()).contains(QCoreApplication::applicationPid()));
}

void TestPortDiagnostics::linkToAHeldPtyFindsTheSameHolder() {
    ScratchPty pty;
    QTemporaryDir dir;
    if (pty.slavePath().isEmpty())
        QSKIP("this system cannot create a pseudo terminal");
    QVERIFY(dir.isValid());
    // Like a socat link or a /dev/serial/by-id name.
    const QString link = dir.filePath(QStringLiteral("ttyStation"));
    QVERIFY(QFile::link(pty.slavePath(), link));
    const qint64 pid = pty.holdInChild();
    QVERIFY(pid > 0);
    QTRY_COMPARE_WITH_TIMEOUT(processesHolding(link), QList<qint64>{pid}, 5000);
}

void TestPortDiagnostics::ptyNobodyOpenedHasNoHolder() {
    ScratchPty pty;
    if (pty.slavePath().isEmpty())
        QSKIP("this system cannot create a pseudo terminal");
    QCOMPARE(processesHolding(pty.slavePath()), QList<qint64>());
}

void TestPortDiagnostics::bareQtPortNameOfAHeldPtyFindsTheChild() {
    ScratchPty pty;
    if (pty.slavePath().isEmpty())
        QSKIP("this system cannot create a pseudo terminal");
    const qint64 pid = pty.holdInChild();
    QVERIFY(pid > 0);
    // QSerialPort::portName() drops "/dev/"; SerialTransport passes that name on.
    const QString bareName = QSerialPort(pty.slavePath()).portName();
    QVERIFY2(bareName.startsWith(QStringLiteral("pts/")), qPrintable(bareName));
    QTRY_COMPARE_WITH_TIMEOUT(processesHolding(bareName), QList<qint64>{pid}, 5000);
}

void TestPortDiagnostics::scratchProcTreeIsReadPidByPid() {
    QTemporaryDir proc;
    QVERIFY(proc.isValid());
    const QString device = proc.filePath(QStringLiteral("ttyUSB0"));
    const QString other = proc.filePath(QStringLiteral("ttyUSB1"));
    QDir root(proc.path());
    for (const char *dir : {"123/fd", "456/fd", "789", "self/fd"})
        QVERIFY(root.mkpath(QString::fromLatin1(dir)));
    QFile(device).open(QIODevice::WriteOnly);
    QFile(other).open(QIODevice::WriteOnly);
    QVERIFY(QFile::link(other, proc.filePath(QStringLiteral("123/fd/0"))));
    QVERIFY(
        QFile::link(QStringLiteral("socket:[4711]"), proc.filePath(QStringLiteral("123/fd/1"))));
    QVERIFY(QFile::link(device, proc.filePath(QStringLiteral("123/fd/3"))));
    QVERIFY(QFile::link(other, proc.filePath(QStringLiteral("456/fd/3"))));
    QVERIFY(QFile::link(device, proc.filePath(QStringLiteral("self/fd/3")))); // not a PID
    QFile comm(proc.filePath(QStringLiteral("123/comm")));
    QVERIFY(comm.open(QIODevice::WriteOnly));
    comm.write("minicom\n");
    comm.close();

    QCOMPARE(processesHolding(device, proc.path()), QList<qint64>{123});
    QCOMPARE(processesHolding(other, proc.path()), (QList<qint64>{123, 456}));
    QCOMPARE(processName(123, proc.path()), QStringLiteral("minicom"));
    QCOMPARE(processName(789, proc.path()), QString());
    const QString message =
        explainOpenFailure(device, QSerialPort::PermissionError, QString(), proc.path());
    QVERIFY2(message.contains(QStringLiteral("held by PID 123 (minicom)")), qPrintable(message));
}

void TestPortDiagnostics::permissionErrorOnAHeldPortNamesTheHolder() {
    ScratchPty pty;
    if (pty.slavePath().isEmpty())
        QSKIP("this system cannot create a pseudo terminal");
    const qint64 pid = pty.holdInChild();
    QVERIFY(pid > 0);
    const QString expected = QStringLiteral("held by PID %1 (sleep)").arg(pid);
    QTRY_VERIFY_WITH_TIMEOUT(explainOpenFailure(pty.slavePath(), QSerialPort::PermissionError,
                                                QStringLiteral("Permission denied"))
                                 .contains(expected),
                             5000);
    const QString message = explainOpenFailure(pty.slavePath(), QSerialPort::PermissionError,
                                               QStringLiteral("Permission denied"));
    QVERIFY2(message.startsWith(pty.slavePath()), qPrintable(message));
    QVERIFY2(!message.contains(QStringLiteral("usermod")), qPrintable(message));
}

void TestPortDiagnostics::secondOpenInThisProgramIsExplainedAsSuch() {
    ScratchPty pty;
    if (pty.slavePath().isEmpty())
        QSKIP("this system cannot create a pseudo terminal");
    QSerialPort first(pty.slavePath());
    QVERIFY2(first.open(QIODevice::ReadWrite), qPrintable(first.errorString()));
    // Qt locks the port it opens, and reports the lock a second open meets as PermissionError.
    QSerialPort second(pty.slavePath());
    QVERIFY(!second.open(QIODevice::ReadWrite));
    QCOMPARE(second.error(), QSerialPort::PermissionError);
    const QString message =
        explainOpenFailure(second.portName(), second.error(), second.errorString());
    const QString expected =
        QStringLiteral("held by PID %1 (").arg(QCoreApplication::applicationPid());
    QVERIFY2(message.contains(expected), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral(", this program)")), qPrintable(message));
    QVERIFY2(!message.contains(QStringLiteral("usermod")), qPrintable(message));
}

void TestPortDiagnostics::permissionErrorWithoutHolderGivesTheGroupFix_data() {
    QTest::addColumn<QString>("group");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("mention");
    const QString dialoutFix = QStringLiteral("sudo usermod -aG dialout $USER");
    QTest::newRow("dialout") << QStringLiteral("dialout") << dialoutFix << QString();
    QTest::newRow("uucp") << QStringLiteral("uucp") << QStringLiteral("sudo usermod -aG uucp $USER")
                          << QStringLiteral("belongs to group uucp");
    QTest::newRow("root") << QStringLiteral("root") << dialoutFix
                          << QStringLiteral("belongs to group root");
}

void TestPortDiagnostics::permissionErrorWithoutHolderGivesTheGroupFix() {
    QFETCH(QString, group);
    QFETCH(QString, command);
    QFETCH(QString, mention);
    const struct group *entry = getgrnam(group.toLocal8Bit().constData());
    if (!entry)
        QSKIP("this system has no such group");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString device = dir.filePath(QStringLiteral("ttyUSB0"));
    QVERIFY(QFile(device).open(QIODevice::WriteOnly));
    if (::chown(QFile::encodeName(device).constData(), uid_t(-1), entry->gr_gid) != 0)
        QSKIP("cannot give a file to that group without being root or a member");
    QCOMPARE(QFileInfo(device).group(), group);

    // An empty /proc: nobody holds the port, so the group must be the reason.
    const QString message = explainOpenFailure(device, QSerialPort::PermissionError,
                                               QStringLiteral("Permission denied"), dir.path());
    QVERIFY2(message.contains(device), qPrintable(message));
    QVERIFY2(message.contains(command), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("log out and back in")), qPrintable(message));
    if (mention.isEmpty())
        QVERIFY2(!message.contains(QStringLiteral("belongs to group")), qPrintable(message));
    else
        QVERIFY2(message.contains(mention), qPrintable(message));
}

void TestPortDiagnostics::anOverLongPortNameIsNoPortNotAGroupProblem() {
    // Issue 38: Qt cannot make the port's lock file for such a name and reports a
    // PermissionError, which was explained as a dialout group to join.
    QTemporaryDir dir;
    QSerialPort port(dir.filePath(QString(300, QLatin1Char('t'))));
    QVERIFY(!port.open(QIODevice::ReadWrite));
    const QString message = explainOpenFailure(port.portName(), port.error(), port.errorString());
    QVERIFY2(message.startsWith(QStringLiteral("There is no such port in ")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("is never 300 characters long")), qPrintable(message));
    QVERIFY2(!message.contains(QStringLiteral("dialout")), qPrintable(message));
}

void TestPortDiagnostics::missingPortSaysNoSuchPort() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString missing = dir.filePath(QStringLiteral("ttyUSB9"));
    QSerialPort port(missing);
    QVERIFY(!port.open(QIODevice::ReadWrite));
    QCOMPARE(port.error(), QSerialPort::DeviceNotFoundError);
    const QString message = explainOpenFailure(missing, port.error(), port.errorString());
    QVERIFY2(message.contains(QStringLiteral("no such port: %1").arg(missing)),
             qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("unplugged")), qPrintable(message));
}

void TestPortDiagnostics::otherErrorsQuoteQtsReason_data() {
    QTest::addColumn<QSerialPort::SerialPortError>("error");
    QTest::addColumn<QString>("reason");
    QTest::addColumn<QString>("meaning");
    QTest::newRow("open") << QSerialPort::OpenError << QStringLiteral("Device is already open")
                          << QStringLiteral("already open in TipScope");
    QTest::newRow("resource") << QSerialPort::ResourceError << QStringLiteral("Input/output error")
                              << QStringLiteral("unplugged");
    QTest::newRow("unsupported") << QSerialPort::UnsupportedOperationError
                                 << QStringLiteral("Invalid argument")
                                 << QStringLiteral("Could not open");
    QTest::newRow("unknown") << QSerialPort::UnknownError << QStringLiteral("Unknown error")
                             << QStringLiteral("Could not open");
}

void TestPortDiagnostics::otherErrorsQuoteQtsReason() {
    QFETCH(QSerialPort::SerialPortError, error);
    QFETCH(QString, reason);
    QFETCH(QString, meaning);
    const QString device = QStringLiteral("/dev/ttyUSB0");
    const QString message = explainOpenFailure(device, error, reason);
    QVERIFY2(message.contains(device), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("(%1).").arg(reason)), qPrintable(message));
    QVERIFY2(message.contains(meaning), qPrintable(message));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestPortDiagnostics)

} // namespace tst_portdiagnostics
#include "tst_portdiagnostics.moc"
