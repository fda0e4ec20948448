// tipscope-cli record and measure end to end: the real binary records the demo at work (or a
// tipscope-sim station on a socat PTY pair) into the CSV the Charts page writes, the replay's
// reader reads it back, and measure finds the joints' recoveries in text and in JSON. Bad
// durations, files and interruptions end as documented.
#include "programrun.h"
#include "testmain.h"

#include "model/recording/chartcsvreader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTest>
#include <sys/stat.h>

namespace tst_clirecord {

using namespace tipscope::testing;
using tipscope::model::ChartCsvReader;
using tipscope::model::ChartRecording;

namespace {

using Run = ProgramRun;

Run run(const QString &program, const QStringList &args, int timeoutMs = 60'000) {
    QProcess p;
    p.start(program, args);
    return finishProcess(p, timeoutMs);
}

Run cli(const QStringList &args, int timeoutMs = 60'000) {
    return runProgram(QStringLiteral("tipscope-cli"), args, timeoutMs);
}

} // namespace

class TestCliRecord : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theDemoAtWorkIsRecordedAndItsJointsRecoveriesMeasured();
    void aStationOnASerialLineIsRecorded();
    void anInterruptedRecordingIsComplete();
    void aHeaderThatCannotBeWrittenWholeLeavesNoFile();
    void aMonitorCsvOnAFullDiskSaysSoOnceMonitorsOnAndFails();
    void aMonitorCsvRowCutPartWayIsTakenBack();
    void measureOfAFifoSaysItWaitsForAWriter();
    void badArgumentsAndFilesAreRefused_data();
    void badArgumentsAndFilesAreRefused();

private:
    QTemporaryDir m_dir;
};

void TestCliRecord::theDemoAtWorkIsRecordedAndItsJointsRecoveriesMeasured() {
    const QString path = m_dir.filePath(QStringLiteral("demo.csv"));
    // The demo makes a joint on port 1 every 15 s, the first 8 s in: 25 s hold at least one.
    const Run r = cli({"--demo-activity", "record", path, "--duration", "25"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.startsWith(QStringLiteral("recorded ")), qPrintable(r.out));
    const auto read = ChartCsvReader::readFile(path);
    QVERIFY2(read, qPrintable(read.error()));
    const ChartRecording *replay = read->get();
    QCOMPARE(replay->channels.size(), 5); // four ports and the feeder
    QCOMPARE(replay->channels.first().tool, QStringLiteral("T210"));
    QCOMPARE(replay->channels.first().highAlarm, 500);
    QVERIFY(replay->lastMs - replay->firstMs > 20'000);

    const Run text = cli({"measure", path});
    QCOMPARE(text.exitCode, 0);
    static const QRegularExpression recovery(QStringLiteral(
        "^port1 recovery \\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d\\.\\d{3}Z (\\d+\\.\\d) s "
        "setpoint 350 °C lowest (\\d+) °C$"));
    const QStringList lines = text.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY2(!lines.isEmpty(), qPrintable(text.err));
    int recoveries = 0;
    for (const QString &line : lines) {
        const auto m = recovery.match(line);
        if (!m.hasMatch())
            continue;
        ++recoveries;
        QVERIFY2(m.captured(1).toDouble() > 0 && m.captured(1).toDouble() < 10, qPrintable(line));
        QVERIFY2(m.captured(2).toInt() < 345, qPrintable(line)); // below the band
    }
    QVERIFY2(recoveries >= 1, qPrintable(text.out));

    const Run json = cli({"measure", "--json", path});
    QCOMPARE(json.exitCode, 0);
    QJsonParseError parse;
    const QJsonArray all = QJsonDocument::fromJson(json.out.toUtf8(), &parse).array();
    QCOMPARE(parse.error, QJsonParseError::NoError);
    QCOMPARE(all.size(), lines.size()); // one object per line of text
    int jsonRecoveries = 0;
    for (const QJsonValue &v : all) {
        const QJsonObject o = v.toObject();
        if (o.value(QStringLiteral("kind")).toString() != QLatin1String("recovery"))
            continue;
        ++jsonRecoveries;
        QCOMPARE(o.value(QStringLiteral("port")).toInt(), 1);
        QCOMPARE(o.value(QStringLiteral("unit")).toString(), QStringLiteral("°C"));
        QCOMPARE(o.value(QStringLiteral("setpoint")).toDouble(), 350.0);
        QVERIFY(o.value(QStringLiteral("durationS")).toDouble() > 0);
        QVERIFY(o.value(QStringLiteral("lowest")).toDouble() < 345);
    }
    QCOMPARE(jsonRecoveries, recoveries);
}

void TestCliRecord::aStationOnASerialLineIsRecorded() {
    SocatPair pair;
    QString error;
    if (!pair.start(&error))
        QSKIP(qPrintable(error));
    SimProcess sim;
    QVERIFY2(!sim.start({"--model", "DDE", "--device", pair.deviceEnd()}, &error).isEmpty(),
             qPrintable(error));
    const QString path = m_dir.filePath(QStringLiteral("serial.csv"));
    const Run r = cli({"--port", pair.hostEnd(), "record", path, "--duration", "3"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const auto read = ChartCsvReader::readFile(path);
    QVERIFY2(read, qPrintable(read.error()));
    const ChartRecording *replay = read->get();
    QCOMPARE(replay->channels.size(), 2); // the DDE's two ports
    QCOMPARE(replay->channels.first().deviceModel, QStringLiteral("DDE-2C"));
    QVERIFY(replay->telemetry->buffer(QStringLiteral("port1"))->size() >= 3);
}

void TestCliRecord::anInterruptedRecordingIsComplete() {
    const QString path = m_dir.filePath(QStringLiteral("interrupted.csv"));
    QProcess p;
    p.start(binaryPath(QStringLiteral("tipscope-cli")), {"--demo", "record", path});
    QVERIFY(p.waitForStarted());
    // Recording has started once the file is there; let rows come, then stop as a service
    // manager (or Ctrl-C) would.
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(path).size() > 4000, 30'000);
    p.terminate();
    QVERIFY(p.waitForFinished(10'000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 0);
    QVERIFY(QString::fromUtf8(p.readAllStandardOutput()).startsWith(QStringLiteral("recorded ")));
    const auto read = ChartCsvReader::readFile(path);
    QVERIFY2(read, qPrintable(read.error()));
}

void TestCliRecord::aHeaderThatCannotBeWrittenWholeLeavesNoFile() {
    // Files may grow to 1 KiB only, less than the header of a station and a feeder: its write
    // fails part way (EFBIG), as on a disk that fills up.
    const QString path = m_dir.filePath(QStringLiteral("limited.csv"));
    const QString command = QStringLiteral("ulimit -f 1; trap '' XFSZ; exec \"$0\" \"$@\"");
    const Run r =
        run(QStringLiteral("/bin/sh"), {"-c", command, binaryPath(QStringLiteral("tipscope-cli")),
                                        "--demo", "record", path, "--duration", "1"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("cannot record to")), qPrintable(r.err));
    QVERIFY2(!QFile::exists(path), "half a header was left behind");
}

void TestCliRecord::aMonitorCsvOnAFullDiskSaysSoOnceMonitorsOnAndFails() {
    // Issue 38: the CSV's rows on a full disk were lost without a word and the run exited 0.
    if (!QFile::exists(QStringLiteral("/dev/full")))
        QSKIP("no /dev/full on this system to simulate a full disk");
    const Run r = cli({"--demo", "monitor", "--interval", "200", "--duration", "2", "--csv",
                       "/dev/full", "--journal", m_dir.filePath(QStringLiteral("full.sqlite"))});
    QVERIFY2(r.exitCode != 0, qPrintable(r.err));
    const QStringList said = r.err.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(said.size(), 1);
    QVERIFY2(said.first().contains(QStringLiteral("No space left on device")), qPrintable(r.err));
    // The journal still works, so the monitor goes on printing every cycle.
    QVERIFY2(r.out.count(QStringLiteral(" P1 ")) >= 5, qPrintable(r.out));
}

// A file size limit cuts a write part way, as a full disk does. The shell ignores the limit's
// signal (a full disk sends none) and sets 2048 bytes (dash counts 512-byte blocks).
void TestCliRecord::aMonitorCsvRowCutPartWayIsTakenBack() {
    const QString path = m_dir.filePath(QStringLiteral("cut.csv"));
    const Run r = run(QStringLiteral("/bin/sh"),
                      {"-c", "trap '' XFSZ; ulimit -f 4; exec \"$0\" \"$@\"",
                       binaryPath(QStringLiteral("tipscope-cli")), "--demo", "monitor",
                       "--interval", "100", "--duration", "4", "--csv", path});
    QVERIFY2(r.exitCode != 0 && r.exitCode != -2, qPrintable(r.err));
    QVERIFY2(r.err.contains(QStringLiteral("File too large")), qPrintable(r.err));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray written = file.readAll();
    QVERIFY2(written.size() > 1000 && written.size() <= 2048, QByteArray::number(written.size()));
    QVERIFY2(written.endsWith('\n'), written.right(80).constData());
    const QList<QByteArray> rows = written.split('\n');
    const QByteArray header = "timestamp,port,tip_c,setpoint_c,power_pct,status";
    QVERIFY(rows.contains(header));
    for (const QByteArray &row : rows)
        if (!row.isEmpty() && !row.startsWith('#'))
            QVERIFY2(row.count(',') == header.count(','), row.constData());
}

void TestCliRecord::measureOfAFifoSaysItWaitsForAWriter() {
    // Issue 38: `measure` of a FIFO that nobody writes to waited without a word.
    const QString fifo = m_dir.filePath(QStringLiteral("measure.fifo"));
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    QProcess p;
    p.start(binaryPath(QStringLiteral("tipscope-cli")), {QStringLiteral("measure"), fifo});
    QString err;
    QVERIFY2(QTest::qWaitFor(
                 [&] {
                     err += QString::fromUtf8(p.readAllStandardError());
                     return err.contains(QStringLiteral("is a FIFO: waiting"));
                 },
                 10000),
             qPrintable(err));
    // A writer comes: the recording is measured, and the run ends as with a file.
    QFile writer(fifo);
    QVERIFY(writer.open(QIODevice::WriteOnly));
    writer.write("time,port1 tip [\xc2\xb0"
                 "C],events\n2026-01-01T00:00:00.000Z,350,\n");
    writer.close();
    QVERIFY(p.waitForFinished(10000));
    QVERIFY2(p.exitCode() == 0, qPrintable(err + QString::fromUtf8(p.readAllStandardError())));
}

void TestCliRecord::badArgumentsAndFilesAreRefused_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QString csv = m_dir.filePath(QStringLiteral("x.csv"));
    for (const char *d : {"nan", "inf", "-1", "1e300", "soon", ""})
        QTest::addRow("record --duration '%s'", d)
            << QStringList{"--demo", "record", csv, "--duration", d} << 1 << "--duration takes";
    QTest::newRow("record without a file")
        << QStringList{"--demo", "record"} << 1 << "record takes one FILE";
    QTest::newRow("record two files")
        << QStringList{"--demo", "record", csv, csv} << 1 << "record takes one FILE";
    QTest::newRow("record into no folder")
        << QStringList{"--demo", "record", "/no/such/folder/x.csv"} << 1 << "no such folder";
    QTest::newRow("record without a line") << QStringList{"record", csv} << 1 << "say where";
    QTest::newRow("measure without a file") << QStringList{"measure"} << 1 << "measure takes";
    QTest::newRow("measure a missing file")
        << QStringList{"measure", m_dir.filePath(QStringLiteral("missing.csv"))} << 2
        << "missing.csv, ";
    QTest::newRow("measure a file that is no recording")
        << QStringList{"measure", QCoreApplication::applicationFilePath()} << 2 << "binary data";
}

void TestCliRecord::badArgumentsAndFilesAreRefused() {
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    const Run r = cli(args);
    QCOMPARE(r.exitCode, exitCode);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("x.csv"))));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCliRecord)

} // namespace tst_clirecord
#include "tst_clirecord.moc"
