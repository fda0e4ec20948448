// tipscope-cli --workspace end to end: the real binary on a workspace of simulated lines (socat
// PTY pairs with tipscope-sim, tipscope-sim on TCP, the demo line). Every line's output comes
// prefixed with its name; a dead line is reported under its name and never keeps the others from
// answering; monitor --csv writes a file per line, or one file with a line column; a bad
// workspace file is refused naming the line and the field.
#include "programrun.h"
#include "testmain.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace tst_cliworkspace {

using namespace tipscope::testing;

namespace {

ProgramRun runCli(const QStringList &args, int timeoutMs = 90000) {
    QProcess p;
    p.start(binaryPath(QStringLiteral("tipscope-cli")), args);
    return finishProcess(p, timeoutMs);
}

QJsonObject line(const QString &name, const QJsonObject &connection) {
    return {{QStringLiteral("name"), name}, {QStringLiteral("connection"), connection}};
}
QJsonObject serial(const QString &port) {
    return {{QStringLiteral("kind"), QStringLiteral("serial")}, {QStringLiteral("port"), port}};
}
QJsonObject tcp(const QString &where) {
    return {{QStringLiteral("kind"), QStringLiteral("tcp")}, {QStringLiteral("address"), where}};
}
QJsonObject demo() {
    return {{QStringLiteral("kind"), QStringLiteral("demo")}};
}

// Nothing listens on port 1 of the loopback: a line there is refused at once, every time.
const QString kDeadServer = QStringLiteral("127.0.0.1:1");

// The lines of `text` that start with "[name] ", without the prefix.
QStringList linesOf(const QString &text, const QString &name) {
    const QString prefix = QStringLiteral("[%1] ").arg(name);
    QStringList out;
    for (const QString &l : text.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        if (l.startsWith(prefix))
            out.append(l.mid(prefix.size()));
    return out;
}

QString readAll(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

} // namespace

class TestCliWorkspace : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void detectRunsOnEveryLineEachLinePrefixedWithItsName();
    void detectWithJsonPrintsOneDocumentForTheWholeWorkspace();
    void monitorWritesACsvFilePerLineWhileADeadLineWaits();
    void monitorWritesOneCsvFileWithALineColumnWhenAsked();
    void aBadWorkspaceIsRefusedNamingTheLineAndTheField();
    void aCommandThatIsNotForEveryLineIsRefused();
    void aLineNameCannotTakeItsCsvOutOfTheFolder();
    void twoLinesWhoseFilesWouldMeetAreRefused();

private:
    QString writeWorkspace(const QJsonArray &lines);
    QTemporaryDir m_dir;
};

void TestCliWorkspace::initTestCase() {
    QVERIFY(m_dir.isValid());
}

QString TestCliWorkspace::writeWorkspace(const QJsonArray &lines) {
    static int count = 0;
    const QString path = m_dir.filePath(QStringLiteral("workspace-%1.json").arg(++count));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(
        QJsonDocument(QJsonObject{{QStringLiteral("format"), QStringLiteral("tipscope-workspace")},
                                  {QStringLiteral("version"), 1},
                                  {QStringLiteral("lines"), lines}})
            .toJson());
    return path;
}

void TestCliWorkspace::detectRunsOnEveryLineEachLinePrefixedWithItsName() {
    SimOnSocat withFeeder, withoutAddresses;
    SimProcess server;
    QString error;
    const QString portA = withFeeder.start({"--model", "DDE", "--feeder"}, &error);
    if (portA.isEmpty() && error.contains(QStringLiteral("socat is not installed")))
        QSKIP(qPrintable(error));
    QVERIFY2(!portA.isEmpty(), qPrintable(error));
    const QString portB = withoutAddresses.start({"--model", "DDR"}, &error);
    QVERIFY2(!portB.isEmpty(), qPrintable(error));
    const QString where = server.start({"--model", "DME", "--tcp", "127.0.0.1:0"}, &error);
    QVERIFY2(!where.isEmpty(), qPrintable(error));
    const QString workspace = writeWorkspace({line(QStringLiteral("cell-1"), serial(portA)),
                                              line(QStringLiteral("cell-2"), serial(portB)),
                                              line(QStringLiteral("wave-1"), tcp(where)),
                                              line(QStringLiteral("gone"), tcp(kDeadServer))});
    QVERIFY(!workspace.isEmpty());

    const ProgramRun r = runCli({"--workspace", workspace, "detect"});
    QCOMPARE(r.exitCode, 5); // the dead line's: the worst of the lines'
    QCOMPARE(
        linesOf(r.out, QStringLiteral("cell-1")),
        QStringList({QStringLiteral("01 DDE-2C DDE 9996780"), QStringLiteral("10 SFR-A SFR -")}));
    QCOMPARE(linesOf(r.out, QStringLiteral("cell-2")), QStringList{QStringLiteral("-- DDR DDR -")});
    QCOMPARE(linesOf(r.out, QStringLiteral("wave-1")),
             QStringList{QStringLiteral("01 DME-2C DME 9996780")});
    QVERIFY(linesOf(r.out, QStringLiteral("gone")).isEmpty());
    const QStringList dead = linesOf(r.err, QStringLiteral("gone"));
    QCOMPARE(dead.size(), 1);
    QVERIFY2(dead.first().startsWith(QStringLiteral("tipscope-cli: cannot open")),
             qPrintable(r.err));
    // Every line of output says whose it is.
    for (const QString &l : r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        QVERIFY2(l.startsWith(QLatin1Char('[')), qPrintable(l));
}

void TestCliWorkspace::detectWithJsonPrintsOneDocumentForTheWholeWorkspace() {
    const QString workspace = writeWorkspace({line(QStringLiteral("bench-a"), demo()),
                                              line(QStringLiteral("gone"), tcp(kDeadServer)),
                                              line(QStringLiteral("bench-b"), demo())});
    QVERIFY(!workspace.isEmpty());

    const ProgramRun r = runCli({"--workspace", workspace, "detect", "--json"});
    QCOMPARE(r.exitCode, 5); // the dead line's
    QJsonParseError parsed{};
    const QJsonObject doc = QJsonDocument::fromJson(r.out.toUtf8(), &parsed).object();
    QVERIFY2(parsed.error == QJsonParseError::NoError, qPrintable(r.out));
    QCOMPARE(doc.value(QStringLiteral("command")).toString(), QStringLiteral("detect"));
    QVERIFY(doc.value(QStringLiteral("workspace")).toString().endsWith(QStringLiteral(".json")));
    const QJsonArray lines = doc.value(QStringLiteral("lines")).toArray();
    QCOMPARE(lines.size(), 3);
    QStringList names;
    for (const QJsonValue &l : lines)
        names << l[QStringLiteral("line")].toString();
    QCOMPARE(names, QStringList({"bench-a", "gone", "bench-b"})); // the file's order
    for (int i : {0, 2}) {
        const QJsonObject working = lines.at(i).toObject();
        QCOMPARE(working.value(QStringLiteral("exitCode")).toInt(), 0);
        QStringList models;
        for (const QJsonValue &d : working.value(QStringLiteral("devices")).toArray())
            models << d[QStringLiteral("model")].toString();
        QCOMPARE(models, QStringList({"DME-2C", "SFR-A"}));
        QVERIFY(!working.contains(QStringLiteral("messages")));
    }
    const QJsonObject dead = lines.at(1).toObject();
    QCOMPARE(dead.value(QStringLiteral("exitCode")).toInt(), 5);
    QVERIFY(!dead.contains(QStringLiteral("devices")));
    const QJsonArray said = dead.value(QStringLiteral("messages")).toArray();
    QCOMPARE(said.size(), 1);
    QVERIFY2(said.first().toString().startsWith(QStringLiteral("tipscope-cli: cannot open")),
             qPrintable(r.out));
    // Standard error still says it, under the line's name.
    QCOMPARE(linesOf(r.err, QStringLiteral("gone")), QStringList{said.first().toString()});
}

void TestCliWorkspace::monitorWritesACsvFilePerLineWhileADeadLineWaits() {
    const QString workspace = writeWorkspace({line(QStringLiteral("bench-a"), demo()),
                                              line(QStringLiteral("bench-b"), demo()),
                                              line(QStringLiteral("gone"), tcp(kDeadServer))});
    const QString csv = m_dir.filePath(QStringLiteral("plant.csv"));
    const ProgramRun r =
        runCli({"--workspace", workspace, "monitor", "--interval", "200", "--duration", "4",
                "--csv", csv, "--journal", m_dir.filePath(QStringLiteral("journal.sqlite"))});
    QCOMPARE(r.exitCode, 5);
    for (const QString &name : {QStringLiteral("bench-a"), QStringLiteral("bench-b")}) {
        const QStringList cycles = linesOf(r.out, name);
        QVERIFY2(cycles.size() >= 3, qPrintable(r.out));
        QVERIFY2(cycles.last().contains(QStringLiteral("P1 ")), qPrintable(cycles.last()));
        const QStringList rows = readAll(m_dir.filePath(QStringLiteral("plant-%1.csv").arg(name)))
                                     .split(QLatin1Char('\n'));
        QVERIFY2(rows.size() > 5, qPrintable(rows.join(QLatin1Char('\n'))));
        QVERIFY2(rows.at(0).startsWith(QStringLiteral("# 01 DME-2C DME")), qPrintable(rows.at(0)));
        QCOMPARE(rows.at(1), QStringLiteral("timestamp,port,tip_c,setpoint_c,power_pct,status"));
    }
    // The dead line said once that it cannot open, waited, and wrote nothing.
    QVERIFY(linesOf(r.out, QStringLiteral("gone")).isEmpty());
    QCOMPARE(linesOf(r.err, QStringLiteral("gone")).filter(QStringLiteral("cannot open")).size(),
             1);
    QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("plant-gone.csv"))));
    QVERIFY(!QFile::exists(csv));
}

void TestCliWorkspace::monitorWritesOneCsvFileWithALineColumnWhenAsked() {
    const QString workspace = writeWorkspace(
        {line(QStringLiteral("bench-a"), demo()), line(QStringLiteral("bench, b"), demo())});
    const QString csv = m_dir.filePath(QStringLiteral("one.csv"));
    const ProgramRun r = runCli({"--workspace", workspace, "monitor", "--interval", "200",
                                 "--duration", "3", "--csv", csv, "--csv-one-file", "--journal",
                                 m_dir.filePath(QStringLiteral("journal.sqlite"))});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QStringList rows = readAll(csv).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY(rows.size() > 4);
    QCOMPARE(rows.at(0), QStringLiteral("timestamp,line,port,tip_c,setpoint_c,power_pct,status"));
    QVERIFY(rows.contains(QStringLiteral("# bench-a: 01 DME-2C DME 9996780")));
    QCOMPARE(rows.filter(QStringLiteral("# ")).size(), 2);
    // A name with a comma is one quoted cell.
    QVERIFY(!rows.filter(QRegularExpression(QStringLiteral("^[^,]+,bench-a,1,"))).isEmpty());
    QVERIFY(!rows.filter(QRegularExpression(QStringLiteral("^[^,]+,\"bench, b\",2,"))).isEmpty());
    QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("one-bench-a.csv"))));
}

void TestCliWorkspace::aBadWorkspaceIsRefusedNamingTheLineAndTheField() {
    QJsonObject bad = line(QStringLiteral("wave-1"), serial(QStringLiteral("/dev/ttyUSB0")));
    QJsonObject connection = serial(QStringLiteral("/dev/ttyUSB0"));
    connection.insert(QStringLiteral("baud"), QStringLiteral("fast"));
    bad.insert(QStringLiteral("connection"), connection);
    const QString workspace = writeWorkspace({line(QStringLiteral("cell-1"), demo()), bad});
    const ProgramRun r = runCli({"--workspace", workspace, "detect"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral(
                 "line 2 (wave-1): connection.baud must be a whole number from 50 to 4000000")),
             qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
}

void TestCliWorkspace::aCommandThatIsNotForEveryLineIsRefused() {
    const QString workspace = writeWorkspace({line(QStringLiteral("cell-1"), demo())});
    const ProgramRun r = runCli({"--workspace", workspace, "write", "ST1", "300"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("--workspace runs detect, monitor, dump or joints")),
             qPrintable(r.err));
    const ProgramRun both = runCli({"--demo", "--workspace", workspace, "detect"});
    QCOMPARE(both.exitCode, 1);
    const ProgramRun oneFile = runCli({"--demo", "monitor", "--csv-one-file"});
    QCOMPARE(oneFile.exitCode, 1);
    QVERIFY2(oneFile.err.contains(QStringLiteral("--csv-one-file goes with --workspace")),
             qPrintable(oneFile.err));
}

void TestCliWorkspace::aLineNameCannotTakeItsCsvOutOfTheFolder() {
    // Issue 38: "out-/../../ESCAPED.csv" is two folders up once "out-" exists.
    QTemporaryDir top;
    const QDir folder(top.filePath(QStringLiteral("a/b")));
    QVERIFY(folder.mkpath(QStringLiteral("out-")));
    const QString workspace = writeWorkspace({line(QStringLiteral("/../../ESCAPED"), demo())});
    const ProgramRun r =
        runCli({"--workspace", workspace, "monitor", "--interval", "200", "--duration", "2",
                "--csv", folder.filePath(QStringLiteral("out.csv")), "--journal",
                top.filePath(QStringLiteral("journal.sqlite"))});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(!QFile::exists(top.filePath(QStringLiteral("a/ESCAPED.csv"))));
    const QStringList rows =
        readAll(folder.filePath(QStringLiteral("out-_.._.._ESCAPED.csv"))).split(QLatin1Char('\n'));
    QVERIFY2(rows.size() > 3, qPrintable(folder.entryList().join(QLatin1Char(' '))));
}

void TestCliWorkspace::twoLinesWhoseFilesWouldMeetAreRefused() {
    const QString workspace =
        writeWorkspace({line(QStringLiteral("a/b"), demo()), line(QStringLiteral("a\\b"), demo())});
    const ProgramRun r = runCli({"--workspace", workspace, "monitor", "--duration", "1", "--csv",
                                 m_dir.filePath(QStringLiteral("meet.csv"))});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("lines a/b and a\\b would both write")),
             qPrintable(r.err));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCliWorkspace)

} // namespace tst_cliworkspace
#include "tst_cliworkspace.moc"
