// Workspace files: what is written reads back equal, atomically replaced; a file that is not a
// workspace, of a later version, with duplicate line names or a wrong field is refused with the
// line and the field named.
#include "model/workspace/workspacefile.h"
#include "testmain.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

namespace tst_workspacefile {

using namespace tipscope;
using namespace tipscope::model;

namespace {

WorkspaceLine serialLine() {
    WorkspaceLine l;
    l.name = QStringLiteral("cell-3");
    l.cell = QStringLiteral("Cell 3");
    l.location = QStringLiteral("Hall B, bench 2");
    l.session.line.kind = link::LineSettings::Kind::Serial;
    l.session.line.serial.portName = QStringLiteral("/dev/ttyUSB0");
    l.session.line.serial.baudRate = 38400;
    l.session.line.serial.parity = QSerialPort::EvenParity;
    l.session.line.serial.stopBits = QSerialPort::TwoStop;
    l.session.line.queue.robotAddress = 5;
    l.session.line.queue.turnaroundMs = 150;
    l.session.line.queue.retries = 3;
    l.session.line.reconnectIntervalMs = 2500;
    l.session.addressing = Session::Addressing::With;
    l.session.targetAddress = 7;
    l.deviceNames = {{7, QStringLiteral("Rework station")}, {10, QStringLiteral("Feeder")}};
    JointLimits limits;
    limits.maxRecoveryMs = 4000;
    limits.maxDipK = 70;
    JointLimitRules rules(limits);
    rules.add(JointLimitRule{1, QStringLiteral("C245"), 3500, 60, std::nullopt});
    l.jointLimits = rules;
    l.context = {QStringLiteral("WO-1234"), QStringLiteral("SN-0042"), QStringLiteral("ana")};
    return l;
}

WorkspaceLine tcpLine() {
    WorkspaceLine l;
    l.name = QStringLiteral("wave-1");
    l.session.line.kind = link::LineSettings::Kind::Tcp;
    l.session.line.tcpHost = QStringLiteral("192.168.1.20");
    l.session.line.tcpPort = 4001;
    l.session.scanAllAddresses = true;
    l.deviceNames = {{-1, QStringLiteral("Bench without addresses")}};
    return l;
}

void compareLines(const WorkspaceLine &a, const WorkspaceLine &b) {
    QCOMPARE(a.name, b.name);
    QCOMPARE(a.cell, b.cell);
    QCOMPARE(a.location, b.location);
    const Session::Settings &s = a.session, &t = b.session;
    QCOMPARE(int(s.line.kind), int(t.line.kind));
    QCOMPARE(s.line.serial.portName, t.line.serial.portName);
    QCOMPARE(s.line.serial.baudRate, t.line.serial.baudRate);
    QCOMPARE(s.line.serial.parity, t.line.serial.parity);
    QCOMPARE(s.line.serial.stopBits, t.line.serial.stopBits);
    QCOMPARE(s.line.tcpHost, t.line.tcpHost);
    QCOMPARE(s.line.tcpPort, t.line.tcpPort);
    QCOMPARE(s.line.queue.robotAddress, t.line.queue.robotAddress);
    QCOMPARE(s.line.queue.turnaroundMs, t.line.queue.turnaroundMs);
    QCOMPARE(s.line.queue.retries, t.line.queue.retries);
    QCOMPARE(s.line.reconnectIntervalMs, t.line.reconnectIntervalMs);
    QCOMPARE(int(s.addressing), int(t.addressing));
    QCOMPARE(s.targetAddress, t.targetAddress);
    QCOMPARE(s.scanAllAddresses, t.scanAllAddresses);
    QCOMPARE(a.deviceNames, b.deviceNames);
    QCOMPARE(a.jointLimits.has_value(), b.jointLimits.has_value());
    if (a.jointLimits)
        QVERIFY(*a.jointLimits == *b.jointLimits);
    QVERIFY(a.context == b.context);
}

QJsonObject workspaceWith(const QJsonArray &lines) {
    return {{QStringLiteral("format"), QStringLiteral("tipscope-workspace")},
            {QStringLiteral("version"), 1},
            {QStringLiteral("lines"), lines}};
}

QJsonObject minimalLine(const QString &name) {
    return {{QStringLiteral("name"), name},
            {QStringLiteral("connection"),
             QJsonObject{{QStringLiteral("kind"), QStringLiteral("tcp")},
                         {QStringLiteral("address"), QStringLiteral("127.0.0.1:4001")}}}};
}

QJsonObject lineWith(const QString &key, const QJsonValue &value) {
    QJsonObject line = minimalLine(QStringLiteral("cell-1"));
    line.insert(key, value);
    return line;
}

} // namespace

class TestWorkspaceFile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aSavedWorkspaceReadsBackEqual();
    void aLineNamingOnlyItsConnectionTakesTheDefaults();
    void theDocumentedExampleReads();
    void aFileOfALaterVersionIsRefusedSayingWhichItReads();
    void aFileThatIsNoWorkspaceIsRefused();
    void duplicateLineNamesAreRefused();
    void aWrongFieldIsRefusedNamingTheLineAndTheField_data();
    void aWrongFieldIsRefusedNamingTheLineAndTheField();
    void anUnreadableFileSaysWhy();
};

void TestWorkspaceFile::aSavedWorkspaceReadsBackEqual() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("sub/plant.tipscope-workspace"));
    WorkspaceFile file;
    file.lines = {serialLine(), tcpLine()};
    const auto saved = file.save(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error()));
    const auto loaded = WorkspaceFile::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error()));
    QCOMPARE(loaded->lines.size(), 2);
    compareLines(loaded->lines.at(0), file.lines.at(0));
    compareLines(loaded->lines.at(1), file.lines.at(1));
    QCOMPARE(loaded->line(QStringLiteral("wave-1"))->deviceName(std::nullopt),
             QStringLiteral("Bench without addresses"));
    QCOMPARE(loaded->line(QStringLiteral("cell-3"))->deviceName(7),
             QStringLiteral("Rework station"));
    QCOMPARE(loaded->line(QStringLiteral("cell-3"))->deviceName(1), QString());
    QVERIFY(!loaded->line(QStringLiteral("nowhere")));
    // The header says what the file is.
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonObject json = QJsonDocument::fromJson(f.readAll()).object();
    QCOMPARE(json.value(QStringLiteral("format")).toString(), QStringLiteral("tipscope-workspace"));
    QCOMPARE(json.value(QStringLiteral("version")).toInt(), 1);
}

void TestWorkspaceFile::aLineNamingOnlyItsConnectionTakesTheDefaults() {
    const auto file =
        WorkspaceFile::fromJson(workspaceWith({minimalLine(QStringLiteral("cell-1"))}));
    QVERIFY2(file.ok(), qPrintable(file.error()));
    const WorkspaceLine &l = file->lines.at(0);
    const Session::Settings defaults;
    QCOMPARE(l.session.line.queue.turnaroundMs, defaults.line.queue.turnaroundMs);
    QCOMPARE(l.session.line.queue.retries, defaults.line.queue.retries);
    QCOMPARE(l.session.line.reconnectIntervalMs, defaults.line.reconnectIntervalMs);
    QCOMPARE(int(l.session.addressing), int(Session::Addressing::Auto));
    QCOMPARE(l.session.line.tcpPort, quint16(4001));
    QVERIFY(!l.jointLimits);
    QVERIFY(l.context.isEmpty());
    QVERIFY(l.deviceNames.isEmpty());
}

void TestWorkspaceFile::theDocumentedExampleReads() {
    const QString docs = QStringLiteral(TIPSCOPE_SOURCE_DIR "/docs/workspace.md");
    QFile f(docs);
    QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(docs));
    const QString text = QString::fromUtf8(f.readAll());
    const qsizetype start = text.indexOf(QStringLiteral("```json\n"));
    QVERIFY(start >= 0);
    const qsizetype end = text.indexOf(QStringLiteral("```"), start + 8);
    const QByteArray example = text.mid(start + 8, end - start - 8).toUtf8();
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(example, &error);
    QVERIFY2(doc.isObject(), qPrintable(error.errorString()));
    const auto file = WorkspaceFile::fromJson(doc.object());
    QVERIFY2(file.ok(), qPrintable(file.error()));
    QCOMPARE(file->lines.size(), 3);
}

void TestWorkspaceFile::aFileOfALaterVersionIsRefusedSayingWhichItReads() {
    QJsonObject json = workspaceWith({minimalLine(QStringLiteral("cell-1"))});
    json.insert(QStringLiteral("version"), 2);
    const auto file = WorkspaceFile::fromJson(json);
    QVERIFY(!file.ok());
    QVERIFY2(file.error().contains(QStringLiteral("workspace version 2")),
             qPrintable(file.error()));
    QVERIFY2(file.error().contains(QStringLiteral("reads version 1")), qPrintable(file.error()));
}

void TestWorkspaceFile::aFileThatIsNoWorkspaceIsRefused() {
    QJsonObject json = workspaceWith({});
    json.insert(QStringLiteral("format"), QStringLiteral("tipscope-profile"));
    const auto other = WorkspaceFile::fromJson(json);
    QVERIFY(!other.ok());
    QVERIFY2(other.error().contains(QStringLiteral("not a TipScope workspace")),
             qPrintable(other.error()));
    json = workspaceWith({});
    json.remove(QStringLiteral("lines"));
    const auto noLines = WorkspaceFile::fromJson(json);
    QVERIFY(!noLines.ok());
    QVERIFY2(noLines.error().contains(QStringLiteral("\"lines\"")), qPrintable(noLines.error()));
}

void TestWorkspaceFile::duplicateLineNamesAreRefused() {
    const auto file = WorkspaceFile::fromJson(
        workspaceWith({minimalLine(QStringLiteral("cell-1")), minimalLine(QStringLiteral("cell-2")),
                       minimalLine(QStringLiteral("cell-1"))}));
    QVERIFY(!file.ok());
    QVERIFY2(file.error().startsWith(QStringLiteral("line 3 (cell-1): the name is already")),
             qPrintable(file.error()));
}

void TestWorkspaceFile::aWrongFieldIsRefusedNamingTheLineAndTheField_data() {
    QTest::addColumn<QJsonObject>("line");
    QTest::addColumn<QString>("expected");
    const auto connection = [](const QJsonObject &c) {
        return lineWith(QStringLiteral("connection"), c);
    };
    QTest::newRow("no name") << QJsonObject{{QStringLiteral("cell"), QStringLiteral("x")}}
                             << QStringLiteral("line 1: every line needs a name");
    QTest::newRow("no connection")
        << QJsonObject{{QStringLiteral("name"), QStringLiteral("cell-1")}}
        << QStringLiteral("line 1 (cell-1): connection is missing");
    QTest::newRow("unknown kind")
        << connection({{QStringLiteral("kind"), QStringLiteral("modem")}})
        << QStringLiteral("line 1 (cell-1): connection.kind must be one of serial, tcp, demo");
    QTest::newRow("serial without port")
        << connection({{QStringLiteral("kind"), QStringLiteral("serial")}})
        << QStringLiteral("line 1 (cell-1): connection.port must name the serial port");
    QTest::newRow("baud as text")
        << connection({{QStringLiteral("kind"), QStringLiteral("serial")},
                       {QStringLiteral("port"), QStringLiteral("/dev/ttyUSB0")},
                       {QStringLiteral("baud"), QStringLiteral("fast")}})
        << QStringLiteral(
               "line 1 (cell-1): connection.baud must be a whole number from 50 to 4000000");
    QTest::newRow("tcp without port number")
        << connection({{QStringLiteral("kind"), QStringLiteral("tcp")},
                       {QStringLiteral("address"), QStringLiteral("10.0.0.1")}})
        << QStringLiteral("line 1 (cell-1): connection.address must be HOST:PORT");
    QTest::newRow("retries out of range")
        << lineWith(QStringLiteral("link"), QJsonObject{{QStringLiteral("retries"), 11}})
        << QStringLiteral("line 1 (cell-1): link.retries must be a whole number from 0 to 10");
    QTest::newRow("addressing mode")
        << lineWith(QStringLiteral("addressing"),
                    QJsonObject{{QStringLiteral("mode"), QStringLiteral("sometimes")}})
        << QStringLiteral("line 1 (cell-1): addressing.mode must be one of auto, with, without");
    QTest::newRow("device without name")
        << lineWith(QStringLiteral("devices"),
                    QJsonArray{QJsonObject{{QStringLiteral("address"), 1}}})
        << QStringLiteral("line 1 (cell-1): devices[0].name must not be empty");
    QTest::newRow("device named twice")
        << lineWith(QStringLiteral("devices"),
                    QJsonArray{QJsonObject{{QStringLiteral("address"), 1},
                                           {QStringLiteral("name"), QStringLiteral("a")}},
                               QJsonObject{{QStringLiteral("address"), 1},
                                           {QStringLiteral("name"), QStringLiteral("b")}}})
        << QStringLiteral("line 1 (cell-1): devices[1] names a device named before");
    QTest::newRow("limits") << lineWith(
                                   QStringLiteral("joint_limits"),
                                   QJsonObject{{QStringLiteral("default"),
                                                QJsonObject{{QStringLiteral("max_dip_k"), 9000}}}})
                            << QStringLiteral("line 1 (cell-1): joint_limits: ");
    QTest::newRow("context") << lineWith(QStringLiteral("context"),
                                         QJsonObject{{QStringLiteral("operator"), 42}})
                             << QStringLiteral("line 1 (cell-1): context: operator must be text");
}

void TestWorkspaceFile::aWrongFieldIsRefusedNamingTheLineAndTheField() {
    QFETCH(QJsonObject, line);
    QFETCH(QString, expected);
    const auto file = WorkspaceFile::fromJson(workspaceWith({line}));
    QVERIFY(!file.ok());
    QVERIFY2(file.error().startsWith(expected), qPrintable(file.error()));
}

void TestWorkspaceFile::anUnreadableFileSaysWhy() {
    QTemporaryDir dir;
    const QString missing = dir.filePath(QStringLiteral("missing.json"));
    const auto none = WorkspaceFile::load(missing);
    QVERIFY(!none.ok());
    QVERIFY2(none.error().startsWith(QStringLiteral("cannot read the workspace")),
             qPrintable(none.error()));
    const QString broken = dir.filePath(QStringLiteral("broken.json"));
    QFile f(broken);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\"format\": \"tipscope-workspace\", ");
    f.close();
    const auto bad = WorkspaceFile::load(broken);
    QVERIFY(!bad.ok());
    QVERIFY2(bad.error().contains(QStringLiteral("is not a JSON object")), qPrintable(bad.error()));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestWorkspaceFile)

} // namespace tst_workspacefile
#include "tst_workspacefile.moc"
