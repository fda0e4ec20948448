// The charts' CSV: what an export or a recording writes reads back exactly for replay, files the
// reader cannot use fully are refused with a message naming the line and the problem, and the
// recorder writes each new sample once, in time order. An export of a window reaching into a
// tiered history's summaries says where its samples start.
#include "model/recording/chartcsv.h"
#include "model/recording/chartcsvreader.h"
#include "model/recording/chartrecorder.h"
#include "testmain.h"

#include <QBuffer>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <csignal>
#include <sys/resource.h>

namespace tst_chartscsv {

using namespace tipscope;
using namespace tipscope::model;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;
const QStringList kPortSeries = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                 QStringLiteral("power"), QStringLiteral("status")};
const QStringList kFeederSeries = {QStringLiteral("fed"), QStringLiteral("speed"),
                                   QStringLiteral("feeding")};

ChartChannel channel(const QString &id, int port, const QStringList &series) {
    ChartChannel c;
    c.key = QStringLiteral("01/") + id;
    c.id = id;
    c.port = port;
    c.series = series;
    c.deviceModel = port ? QStringLiteral("DME-4C") : QStringLiteral("SFR");
    c.address = port ? QStringLiteral("01") : QStringLiteral("10");
    c.softwareVersion = QStringLiteral("9996780");
    c.tool = port ? QStringLiteral("T245") : QString();
    if (port == 1) {
        c.highAlarm = 450;
        c.lowAlarm = 150;
    }
    return c;
}

// Two ports sampled at different instants (so rows have empty cells), a feeder, and events.
void fill(Telemetry &t, QList<ChartChannel> &channels, ChartEvents &events) {
    channels = {channel(QStringLiteral("port1"), 1, kPortSeries),
                channel(QStringLiteral("port2"), 2, kPortSeries),
                channel(QStringLiteral("feeder"), 0, kFeederSeries)};
    for (const ChartChannel &c : std::as_const(channels))
        t.ensureBuffer(c.key, c.series);
    for (int i = 0; i < 500; ++i) {
        t.append(channels.at(0).key, kT0 + i * 100, {25 + i, 350, 1000 - i, i > 300 ? 1 : 0});
        if (i % 3 == 0) // same instant as port 1 now and then, otherwise in between
            t.append(channels.at(1).key, kT0 + i * 100 + (i % 2 ? 0 : 37), {351, 350, 123, 11});
        if (i % 10 == 0)
            t.append(channels.at(2).key, kT0 + i * 100, {i * 5, 125, 1});
        if (i == 250) // port 2 stops answering for a while
            t.markGap(channels.at(1).key, kT0 + i * 100 + 50, TelemetryGap::Cause::NoAnswer);
    }
    events.add({kT0 + 30'000, Event::Kind::Status, Event::Severity::Info, QStringLiteral("port1"),
                QStringLiteral("Working → Stand"), QString()});
    events.add({kT0 + 30'050, Event::Kind::Write, Event::Severity::Info, QStringLiteral("@01"),
                QStringLiteral("ST1 = 350 °C, \"saved\""), QString()});
}

void compareSamples(const Telemetry &a, const QString &keyA, const Telemetry &b,
                    const QString &keyB) {
    const auto *x = a.buffer(keyA);
    const auto *y = b.buffer(keyB);
    QVERIFY(x && y);
    QCOMPARE(y->seriesNames(), x->seriesNames());
    for (int s = 0; s < x->seriesCount(); ++s) {
        const auto left = x->samples(s, kT0 - 1, kT0 + 3600'000);
        const auto right = y->samples(s, kT0 - 1, kT0 + 3600'000);
        QCOMPARE(right.size(), left.size());
        for (qsizetype i = 0; i < left.size(); ++i) {
            QCOMPARE(right.at(i).timeMs, left.at(i).timeMs);
            QCOMPARE(right.at(i).value, left.at(i).value);
        }
    }
}

QString header() {
    return QStringLiteral("# TipScope chart data, format 1\ntime,port1 tip [°C],events\n");
}
} // namespace

class TestChartsCsv : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void exportReadsBackExactlyForReplay_data();
    void exportReadsBackExactlyForReplay();
    void malformedFilesAreRefusedWithAClearError_data();
    void malformedFilesAreRefusedWithAClearError();
    void aHugeFileIsRefusedBeforeItIsRead();
    void anExportReachingIntoSummariesSaysWhereItsSamplesStart();
    void recorderWritesEachNewSampleOnceInTimeOrder();
    void aFullDiskStopsTheRecordingWithTheReason();
    void aBatchCutPartWayIsTakenBackToTheLastWholeRow();
};

void TestChartsCsv::exportReadsBackExactlyForReplay_data() {
    QTest::addColumn<TemperatureUnit>("unit");
    QTest::newRow("°C") << TemperatureUnit::Celsius;
    QTest::newRow("°F") << TemperatureUnit::Fahrenheit;
}

void TestChartsCsv::exportReadsBackExactlyForReplay() {
    QFETCH(TemperatureUnit, unit);
    Telemetry live;
    QList<ChartChannel> channels;
    ChartEvents events;
    fill(live, channels, events);
    QBuffer file;
    QVERIFY(file.open(QIODevice::ReadWrite));
    ChartCsvWriter writer(file, channels, unit);
    QVERIFY(writer.writeHeader(QStringLiteral("9.9")));
    QVERIFY(writer.writeWindow(live, events, kT0, kT0 + 3600'000));
    const QString text = QString::fromUtf8(file.data());
    const QString tip = unit == TemperatureUnit::Celsius ? QStringLiteral("port1 tip [°C]")
                                                         : QStringLiteral("port1 tip [°F]");
    QVERIFY2(text.contains(tip), qPrintable(text.left(800)));
    QVERIFY(text.contains(QStringLiteral("port1 power [%]")));
    QVERIFY(text.contains(QStringLiteral("device=DME-4C; address=01; device software=9996780; "
                                         "port=1; tool=T245")));
    QVERIFY(text.contains(QStringLiteral("\n2023-11-14T22:13:20.000Z,")));

    file.seek(0);
    const auto read = ChartCsvReader::read(file);
    QVERIFY2(read, qPrintable(read.error()));
    const ChartRecording *replay = read->get();
    QCOMPARE(replay->software, QStringLiteral("TipScope 9.9"));
    QCOMPARE(replay->channels.size(), 3);
    for (int i = 0; i < 3; ++i) {
        const ChartChannel &c = replay->channels.at(i);
        QCOMPARE(c.id, channels.at(i).id);
        QCOMPARE(c.port, channels.at(i).port);
        QCOMPARE(c.deviceModel, channels.at(i).deviceModel);
        QCOMPARE(c.softwareVersion, channels.at(i).softwareVersion);
        QCOMPARE(c.tool, channels.at(i).tool);
        QCOMPARE(c.highAlarm, channels.at(i).highAlarm);
        compareSamples(live, channels.at(i).key, *replay->telemetry, c.key);
    }
    // The gap is in the file, and the replay has it where the live history had it.
    QVERIFY(text.contains(QStringLiteral("port2 gap: no-answer")));
    const auto liveGaps = live.buffer(channels.at(1).key)->gaps().within(kT0, kT0 + 3600'000);
    const auto replayGaps =
        replay->telemetry->buffer(replay->channels.at(1).key)->gaps().within(kT0, kT0 + 3600'000);
    QCOMPARE(liveGaps.size(), 1);
    QCOMPARE(replayGaps.size(), 1);
    QCOMPARE(replayGaps.first().startMs, liveGaps.first().startMs);
    QCOMPARE(replayGaps.first().endMs, liveGaps.first().endMs);
    QCOMPARE(replayGaps.first().cause, TelemetryGap::Cause::NoAnswer);
    QVERIFY(
        replay->telemetry->buffer(replay->channels.at(0).key)->gaps().within(0, kT0 * 2).isEmpty());
    const QList<ChartEvent> back = replay->events.between(kT0, kT0 + 3600'000);
    QCOMPARE(back.size(), 2);
    QCOMPARE(back.at(1).kind, Event::Kind::Write);
    QCOMPARE(back.at(1).scope, QStringLiteral("@01"));
    QCOMPARE(back.at(1).text, QStringLiteral("ST1 = 350 °C, \"saved\""));
    QCOMPARE(back.at(0).timeMs, kT0 + 30'000);
}

void TestChartsCsv::malformedFilesAreRefusedWithAClearError_data() {
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("expected");
    const QByteArray h = header().toUtf8();
    const QByteArray row = "2023-11-14T22:13:20.000Z,350,\n";
    QTest::newRow("empty") << QByteArray() << "the file is empty";
    QTest::newRow("only comments") << QByteArray("# hello\n") << "only comments";
    QTest::newRow("not a chart csv")
        << QByteArray("a,b\n1,2\n") << "line 1: the header row should start with \"time\"";
    QTest::newRow("unknown column") << QByteArray("time,banana\n") << "column 2 \"banana\"";
    QTest::newRow("wrong unit") << QByteArray("time,port1 tip [K]\n")
                                << "the unit should be \"°C\"";
    QTest::newRow("duplicate column")
        << QByteArray("time,port1 tip [°C],port1 tip [°C]\n") << "appears twice";
    QTest::newRow("header but no rows") << h << "a header but no rows";
    QTest::newRow("too many cells") << h + "2023-11-14T22:13:20.000Z,1,,\n"
                                    << "line 3: 4 cells, but the header has 3 columns";
    QTest::newRow("bad time") << h + "yesterday,350,\n"
                              << "line 3: \"yesterday\" is not an ISO 8601 time";
    QTest::newRow("bad number") << h + "2023-11-14T22:13:20.000Z,hot,\n"
                                << "line 3: column 2: \"hot\" is not a number";
    QTest::newRow("rows out of order") << h + row + "2023-11-14T22:13:19.000Z,350,\n"
                                       << "line 4: the time 2023-11-14T22:13:19.000Z is earlier";
    QTest::newRow("channel half filled")
        << QByteArray("time,port1 tip [°C],port1 power [%]\n2023-11-14T22:13:20.000Z,350,\n")
        << "port1 has values in some of its columns but not all";
    QTest::newRow("not UTF-8") << QByteArray("time,port1 tip [\xb0"
                                             "C]\n")
                               << "line 1: the text is not UTF-8";
    QTest::newRow("binary") << QByteArray("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)
                            << "binary data, not CSV text";
    QTest::newRow("unclosed quote") << h + "2023-11-14T22:13:20.000Z,350,\"port1 status: x\n"
                                    << "line 3: a quoted cell is not closed";
    QTest::newRow("over-long line") << h + QByteArray(70'000, 'x') + "\n"
                                    << "line 3: the line is longer than 65536 bytes";
    QTest::newRow("bad event") << h + "2023-11-14T22:13:20.000Z,350,boom\n"
                               << "line 3: the event \"boom\" is not";
}

void TestChartsCsv::malformedFilesAreRefusedWithAClearError() {
    QFETCH(QByteArray, content);
    QFETCH(QString, expected);
    QBuffer file(&content);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const auto read = ChartCsvReader::read(file);
    QVERIFY(!read);
    QVERIFY2(read.error().contains(expected), qPrintable(read.error()));
}

void TestChartsCsv::aHugeFileIsRefusedBeforeItIsRead() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("huge.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QVERIFY(file.resize(ChartCsvReader::kMaxFileBytes + 1)); // sparse: no disk used
    file.close();
    const auto huge = ChartCsvReader::readFile(path);
    QVERIFY(!huge);
    QVERIFY2(huge.error().startsWith(QStringLiteral("huge.csv, ")), qPrintable(huge.error()));
    QVERIFY2(huge.error().contains(QStringLiteral("replay reads files up to 1024 MB")),
             qPrintable(huge.error()));
    const auto missing = ChartCsvReader::readFile(dir.filePath(QStringLiteral("missing.csv")));
    QVERIFY(!missing);
    QVERIFY2(missing.error().startsWith(QStringLiteral("missing.csv, ")),
             qPrintable(missing.error()));
}

void TestChartsCsv::recorderWritesEachNewSampleOnceInTimeOrder() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rec.csv"));
    Telemetry live;
    const ChartChannel c = channel(QStringLiteral("port1"), 1, kPortSeries);
    live.ensureBuffer(c.key, c.series);
    live.append(c.key, kT0, {100, 350, 0, 0}); // before the recording: not in it
    ChartRecorder recorder(live);
    QCOMPARE(recorder.start(path, {c}, TemperatureUnit::Celsius, QStringLiteral("9.9")), QString());
    live.append(c.key, kT0, {101, 350, 0, 0}); // the same millisecond, after the start
    live.append(c.key, kT0 + 100, {102, 350, 0, 0});
    recorder.flush();
    live.append(c.key, kT0 + 100, {103, 350, 0, 0}); // a batch sharing the last instant
    live.append(c.key, kT0 + 200, {104, 350, 0, 0});
    // An event stamped a little before rows already written must not break the time order.
    recorder.addEvent({kT0 + 50, Event::Kind::Status, Event::Severity::Info,
                       QStringLiteral("port1"), QStringLiteral("Working → Stand"), QString()});
    recorder.flush();
    recorder.stop();
    QCOMPARE(recorder.rowsWritten(), 4); // the late event shares the row of the sample at +100
    const auto read = ChartCsvReader::readFile(path);
    QVERIFY2(read, qPrintable(read.error()));
    const ChartRecording *replay = read->get();
    const auto tips = replay->telemetry->buffer(QStringLiteral("port1"))->samples(0, 0, kT0 + 1000);
    QCOMPARE(tips.size(), 4);
    for (int i = 0; i < 4; ++i)
        QCOMPARE(tips.at(i).value, 101 + i);
    QCOMPARE(replay->events.size(), 1);
}

void TestChartsCsv::aFullDiskStopsTheRecordingWithTheReason() {
    if (!QFile::exists(QStringLiteral("/dev/full")))
        QSKIP("no /dev/full on this system to simulate a full disk");
    Telemetry live;
    const ChartChannel c = channel(QStringLiteral("port1"), 1, kPortSeries);
    live.ensureBuffer(c.key, c.series);
    ChartRecorder recorder(live);
    const QString error =
        recorder.start(QStringLiteral("/dev/full"), {c}, TemperatureUnit::Celsius, QString());
    QVERIFY2(!error.isEmpty(), "writing the header to a full disk must fail");
    QVERIFY(!recorder.isRecording());
    QVERIFY(!recorder
                 .start(QStringLiteral("/no/such/folder/rec.csv"), {c}, TemperatureUnit::Celsius,
                        QString())
                 .isEmpty());
}

// A file size limit cuts a write part way, as a full disk does: the kernel takes what fits and
// refuses the rest. The file must still end with a whole row that replay reads, and the
// recorder must count only the rows that are in it.
void TestChartsCsv::aBatchCutPartWayIsTakenBackToTheLastWholeRow() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rec.csv"));
    Telemetry live;
    const ChartChannel c = channel(QStringLiteral("port1"), 1, kPortSeries);
    live.ensureBuffer(c.key, c.series);
    ChartRecorder recorder(live);
    QSignalSpy failed(&recorder, &ChartRecorder::failed);
    QVERIFY(failed.isValid());
    QCOMPARE(recorder.start(path, {c}, TemperatureUnit::Celsius, QString()), QString());
    const qint64 headerBytes = QFileInfo(path).size();

    rlimit before{};
    QVERIFY(::getrlimit(RLIMIT_FSIZE, &before) == 0);
    rlimit limited = before;
    limited.rlim_cur = rlim_t(headerBytes + 1000);         // about 25 rows, then a row cut part way
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN); // the limit's signal; a disk sends none
    QVERIFY(::setrlimit(RLIMIT_FSIZE, &limited) == 0);
    for (int batch = 0; batch < 20 && failed.isEmpty(); ++batch) {
        for (int i = 0; i < 10; ++i)
            live.append(c.key, kT0 + (batch * 10 + i) * 100, {300 + i, 350, 50, 0});
        recorder.flush();
    }
    QVERIFY(::setrlimit(RLIMIT_FSIZE, &before) == 0);
    std::signal(SIGXFSZ, oldHandler);

    QCOMPARE(failed.size(), 1);
    QVERIFY2(failed.first().first().toString().contains(QStringLiteral("size limit")),
             qPrintable(failed.first().first().toString()));
    QVERIFY(!recorder.isRecording());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray written = file.readAll();
    QVERIFY(written.size() > headerBytes);
    QVERIFY2(written.endsWith('\n'), written.right(80).constData());
    const auto read = ChartCsvReader::readFile(path);
    QVERIFY2(read, qPrintable(read.error()));
    const auto tips =
        read->get()->telemetry->buffer(QStringLiteral("port1"))->samples(0, 0, kT0 + 100'000);
    QCOMPARE(tips.size(), recorder.rowsWritten());
    QCOMPARE(qint64(written.count('\n') - QByteArray(written.left(headerBytes)).count('\n')),
             recorder.rowsWritten());
}

void TestChartsCsv::anExportReachingIntoSummariesSaysWhereItsSamplesStart() {
    Telemetry t;
    TelemetryTiers tiers;
    tiers.fullRateMs = 60'000;
    tiers.historyMs = 3'600'000;
    tiers.bucketMs = 1000;
    t.setTiers(tiers);
    const QList<ChartChannel> channels = {channel(QStringLiteral("port1"), 1, kPortSeries)};
    t.ensureBuffer(channels.at(0).key, kPortSeries);
    for (int i = 0; i < 20 * 600; ++i) // 20 minutes at 10 Hz
        t.append(channels.at(0).key, kT0 + i * 100, {350, 350, 10, 0});
    const TelemetryBuffer &b = *t.buffer(channels.at(0).key);
    QVERIFY(b.summaryCount() > 0);
    QCOMPARE(ChartCsvWriter::fullRateFrom(t, channels, kT0), b.fullRateFrom());
    QVERIFY(!ChartCsvWriter::fullRateFrom(t, channels, b.fullRateFrom()));
    // The file holds exactly the samples from there on.
    QBuffer file;
    file.open(QIODevice::WriteOnly);
    ChartCsvWriter writer(file, channels, TemperatureUnit::Celsius);
    QVERIFY(writer.writeHeader(QStringLiteral("test")));
    QVERIFY(writer.writeWindow(t, ChartEvents(), kT0, b.lastTime() + 1));
    QCOMPARE(writer.rowsWritten(), qint64(b.size()));
    // A single-tier history holds every sample: nothing to say.
    Telemetry single;
    single.ensureBuffer(channels.at(0).key, kPortSeries, 100);
    for (int i = 0; i < 500; ++i)
        single.append(channels.at(0).key, kT0 + i * 100, {350, 350, 10, 0});
    QVERIFY(!ChartCsvWriter::fullRateFrom(single, channels, kT0));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestChartsCsv)

} // namespace tst_chartscsv
#include "tst_chartscsv.moc"
