// Replay keeps the promises of docs/reliability.md whatever the file: every event of a
// recording comes back (none dropped for a cap), and a file is read as a stream with its size
// capped by the bytes actually read (a FIFO too), its comment lines bounded, and the memory it
// takes bounded by twice its size; a read can be followed and cancelled.
#include "model/recording/chartcsvreader.h"
#include "testmain.h"

#include "support/fifowriter.h"

#include <QBuffer>
#include <QElapsedTimer>
#include <QTest>

namespace tst_replay {

using namespace tipscope::model;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;

QByteArray header() {
    return "# TipScope chart data, format 1\n"
           "time,port1 tip [\xc2\xb0"
           "C],port1 setpoint [\xc2\xb0"
           "C],events\n";
}

QByteArray timeText(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs).toUtf8();
}

tipscope::base::Outcome<std::unique_ptr<ChartRecording>>
readBytes(QByteArray bytes, const ChartCsvReader::Options &options = {}) {
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::ReadOnly);
    return ChartCsvReader::read(buffer, options);
}

QByteArray rows(int count, qint64 from = kT0) {
    QByteArray out;
    for (int i = 0; i < count; ++i)
        out += timeText(from + i * 100) + ",350,350,\n";
    return out;
}

// What the GUI records: four ports of six series and a feeder, each sampled on its own clock
// (so a row holds one channel and empty cells for the others), and now and then an event.
QByteArray stationRecording(int rowCount) {
    QByteArray csv = "# TipScope chart data, format 1\ntime";
    for (int p = 1; p <= 4; ++p)
        for (const char *s : {"tip [°C]", "setpoint [°C]", "power [%]", "status", "transistor [°C]",
                              "transformer [°C]"})
            csv += ",port" + QByteArray::number(p) + ' ' + s;
    csv += ",feeder fed [mm],feeder speed [mm/s],feeder feeding,events\n";
    for (int i = 0; i < rowCount; ++i) {
        const int channel = i % 5;
        QByteArray cells[5] = {",,,,,", ",,,,,", ",,,,,", ",,,,,", ",,"};
        cells[channel] = channel < 4 ? "351,350,12.5,0,45,38" : "1520.5,10.0,1";
        csv += timeText(kT0 + i * 50);
        for (const QByteArray &c : cells)
            csv += ',' + c;
        csv += i % 300 == 0 ? ",port1 status: Working \xe2\x86\x92 Stand\n" : ",\n";
    }
    return csv;
}

} // namespace

class TestReplay : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyEventOfTheFileIsReplayed_data();
    void everyEventOfTheFileIsReplayed();
    void aFifoFedPastTheLimitIsRefusedAtTheLimit();
    void aCancelIsHeardWhileAFifoSendsNothing();
    void aFileOfCommentsIsRefusedAtTheBoundNotAtItsEnd();
    void progressFollowsTheBytesReadAndCanCancel();
    void aRecordingTakesLessThanTwiceItsSizeInMemory();
    void aFileDenserThanTipScopeWritesIsRefusedBeforeTwiceItsSize();
};

void TestReplay::everyEventOfTheFileIsReplayed_data() {
    QTest::addColumn<int>("events");
    QTest::newRow("10,001") << 10'001;
    QTest::newRow("30,000") << 30'000;
}

void TestReplay::everyEventOfTheFileIsReplayed() {
    QFETCH(int, events);
    QByteArray csv = header();
    for (int i = 0; i < events; ++i) // a sample and an event every 100 ms
        csv += timeText(kT0 + i * 100) + ",350,350,port1 status: change " + QByteArray::number(i) +
               '\n';
    const auto read = readBytes(csv);
    QVERIFY2(read, qPrintable(read.error()));
    const ChartRecording *replay = read->get();
    QCOMPARE(replay->events.size(), events);
    const QList<ChartEvent> all = replay->events.between(kT0, kT0 + qint64(events) * 100);
    QCOMPARE(all.size(), events);
    QCOMPARE(all.first().timeMs, kT0);
    QCOMPARE(all.first().text, QStringLiteral("change 0"));
    QCOMPARE(all.last().text, QStringLiteral("change %1").arg(events - 1));
}

void TestReplay::aFifoFedPastTheLimitIsRefusedAtTheLimit() {
#ifdef Q_OS_UNIX
    constexpr qint64 kLimit = 1 << 20;
    QTemporaryDir dir;
    // Four times the limit, then the end: a reader that ignores the limit replays it all.
    FifoWriter writer(dir, header() + rows(4 * kLimit / 34), true);
    QVERIFY(writer.ok());
    ChartCsvReader::Options options;
    options.maxBytes = kLimit;
    const auto read = ChartCsvReader::readFile(writer.path(), options);
    QVERIFY2(!read, "the limit was ignored");
    const QString error = read.error();
    QVERIFY2(error.contains(QStringLiteral("larger than 1 MB")), qPrintable(error));
    QVERIFY2(error.startsWith(QStringLiteral("fifo.csv, ")), qPrintable(error));
#else
    QSKIP("FIFOs are a Unix thing");
#endif
}

void TestReplay::aCancelIsHeardWhileAFifoSendsNothing() {
#ifdef Q_OS_UNIX
    QTemporaryDir dir;
    FifoWriter writer(dir, header() + rows(10), false); // then silence, the FIFO held open
    QVERIFY(writer.ok());
    QElapsedTimer clock;
    clock.start();
    qint64 seen = 0;
    ChartCsvReader::Options options;
    options.progress = [&](qint64 bytes) {
        seen = bytes;
        return bytes == 0 || clock.elapsed() < 300; // the person gives up after a moment
    };
    const auto read = ChartCsvReader::readFile(writer.path(), options);
    QVERIFY(!read);
    const QString error = read.error();
    QVERIFY2(error.endsWith(ChartCsvReader::cancelledText()), qPrintable(error));
    QCOMPARE(seen, writer.written());
#else
    QSKIP("FIFOs are a Unix thing");
#endif
}

void TestReplay::aFileOfCommentsIsRefusedAtTheBoundNotAtItsEnd() {
    QByteArray csv;
    for (int i = 0; i < 100'000; ++i)
        csv += "# channel port" + QByteArray::number(i) + ": device=DME-4C; address=01\n";
    csv += header() + rows(10);
    qint64 read = 0;
    ChartCsvReader::Options options;
    options.progress = [&](qint64 bytes) {
        read = bytes;
        return true;
    };
    const auto replay = readBytes(csv, options);
    QVERIFY2(!replay, "a file of comments replayed");
    const QString error = replay.error();
    QVERIFY2(error.contains(QStringLiteral("line 1025: more than 1024 comment lines")),
             qPrintable(error));
    QVERIFY2(read <= 2 * ChartCsvReader::kChunkBytes, qPrintable(QString::number(read)));
}

void TestReplay::progressFollowsTheBytesReadAndCanCancel() {
    const QByteArray csv = header() + rows(100'000); // about 3.4 MB
    QList<qint64> seen;
    ChartCsvReader::Options options;
    options.progress = [&](qint64 bytes) {
        seen.append(bytes);
        return true;
    };
    const auto whole = readBytes(csv, options);
    QVERIFY2(whole, qPrintable(whole.error()));
    QCOMPARE((*whole)->bytes, csv.size());
    QVERIFY(seen.size() > 10);
    QVERIFY(std::is_sorted(seen.cbegin(), seen.cend()));
    QCOMPARE(seen.last(), csv.size());

    seen.clear();
    options.progress = [&](qint64 bytes) {
        seen.append(bytes);
        return bytes < (1 << 20);
    };
    const auto cancelled = readBytes(csv, options);
    QVERIFY(!cancelled);
    QCOMPARE(cancelled.error(), ChartCsvReader::cancelledText());
    QVERIFY(seen.last() < (1 << 20) + ChartCsvReader::kChunkBytes + 1);
}

void TestReplay::aRecordingTakesLessThanTwiceItsSizeInMemory() {
    const QByteArray csv = stationRecording(200'000);
    const auto read = readBytes(csv);
    QVERIFY2(read, qPrintable(read.error()));
    const ChartRecording *replay = read->get();
    QCOMPARE(replay->rows, 200'000);
    QVERIFY(replay->events.size() > 600);
    const qint64 held = replay->memoryBytes();
    QVERIFY2(
        held < 2 * csv.size(),
        qPrintable(QStringLiteral("%1 bytes held for a %2-byte file").arg(held).arg(csv.size())));
}

void TestReplay::aFileDenserThanTipScopeWritesIsRefusedBeforeTwiceItsSize() {
    // 255 channels of one series, every cell filled with one digit: each sample costs its time
    // (8 bytes) and its value in memory for two bytes of file.
    QByteArray head = "time";
    QByteArray cells;
    for (int p = 1; p <= 255; ++p) {
        head += ",port" + QByteArray::number(p) + " tip [°C]";
        cells += ",1";
    }
    QByteArray csv = head + '\n';
    for (int i = 0; i < 40'000; ++i)
        csv += timeText(kT0 + i * 100) + cells + '\n';
    const auto replay = readBytes(csv);
    QVERIFY2(!replay, "a file needing five times its size in memory replayed");
    const QString error = replay.error();
    QVERIFY2(error.contains(QStringLiteral("more than replay allows (twice the file's size)")),
             qPrintable(error));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestReplay)

} // namespace tst_replay
#include "tst_replay.moc"
