// tipscope's command line without a display, as over SSH (no DISPLAY, no WAYLAND_DISPLAY, no
// QT_QPA_PLATFORM): --help and --version print and exit 0, an unknown option is refused with its
// error, and a plain start says there is no display instead of aborting.
#include "programrun.h"
#include "testmain.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace tst_guicommandline {

using namespace tipscope;

namespace {
testing::ProgramRun runWithoutDisplay(const QStringList &args) {
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        e.remove(QLatin1String(name));
    QProcess p;
    p.setProcessEnvironment(e);
    p.start(testing::binaryPath(QStringLiteral("tipscope")), args);
    return testing::finishProcess(p, 30000);
}
} // namespace

class TestGuiCommandLine : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void helpAndVersionWorkWithoutADisplay_data();
    void helpAndVersionWorkWithoutADisplay();
    void anUnknownOptionIsRefusedWithoutADisplay();
    void theWindowWithoutADisplayIsRefusedWithTheReason();
    void aWorkspaceThatCannotBeOpenedIsRefusedWithTheReason();
};

void TestGuiCommandLine::helpAndVersionWorkWithoutADisplay_data() {
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("expected");
    QTest::newRow("--help") << "--help"
                            << "--screenshots <DIR>";
    QTest::newRow("-h") << "-h"
                        << "--port <DEVICE>";
    QTest::newRow("--help-all") << "--help-all"
                                << "--platform";
    QTest::newRow("--version") << "--version"
                               << "TipScope " TIPSCOPE_VERSION;
}

void TestGuiCommandLine::helpAndVersionWorkWithoutADisplay() {
    QFETCH(QString, option);
    QFETCH(QString, expected);
    const testing::ProgramRun r = runWithoutDisplay({option});
    QVERIFY2(r.exitCode == 0, qPrintable(QString::number(r.exitCode) + QLatin1Char(' ') + r.err));
    QVERIFY2(r.out.contains(expected), qPrintable(r.out));
}

void TestGuiCommandLine::anUnknownOptionIsRefusedWithoutADisplay() {
    const testing::ProgramRun r = runWithoutDisplay({QStringLiteral("--bogus")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("bogus")), qPrintable(r.err));
}

void TestGuiCommandLine::theWindowWithoutADisplayIsRefusedWithTheReason() {
    const testing::ProgramRun r = runWithoutDisplay({QStringLiteral("--demo")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("no display")), qPrintable(r.err));
}

void TestGuiCommandLine::aWorkspaceThatCannotBeOpenedIsRefusedWithTheReason() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("absent.json"));
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    e.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    e.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.path()); // the user's settings stay untouched
    e.insert(QStringLiteral("XDG_DATA_HOME"), dir.path());
    QProcess p;
    p.setProcessEnvironment(e);
    p.start(testing::binaryPath(QStringLiteral("tipscope")), {QStringLiteral("--workspace"), path});
    const testing::ProgramRun r = testing::finishProcess(p, 30000);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(path), qPrintable(r.err));
}

TIPSCOPE_TEST_MAIN(TestGuiCommandLine)

} // namespace tst_guicommandline
#include "tst_guicommandline.moc"
