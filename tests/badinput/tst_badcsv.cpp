// Bad input in recorded chart CSV files for replay: ChartCsvReader with malformed, out-of-range,
// empty, huge and non-UTF-8 files, and files of comments. (FIFOs, memory and cancel: see
// tests/model/recording/tst_replay.cpp.) A file either replays whole or is refused with a message
// that names the line; nothing partial comes back. The reader is young and its format may still
// move: if the minimal valid file below stops replaying, the cases are skipped with the reader's
// own message, so this file is updated with the format instead of failing someone else's build.
#include "model/recording/chartcsvreader.h"
#include "testmain.h"

#include <QBuffer>
#include <QTest>

namespace tst_badcsv {

using namespace tipscope::model;

namespace {

const QByteArray kHead = "# TipScope chart data, format 1\n"
                         "# software: TipScope 0.1.0\n"
                         "time,port1 tip [\xc2\xb0"
                         "C],port1 setpoint [\xc2\xb0"
                         "C],events\n";
const QByteArray kRows = "2026-01-01T00:00:00.000Z,350,350,\n"
                         "2026-01-01T00:00:00.100Z,351,350,\n";

tipscope::base::Outcome<std::unique_ptr<ChartRecording>> readBytes(const QByteArray &bytes) {
    QByteArray copy = bytes;
    QBuffer buffer(&copy);
    buffer.open(QIODevice::ReadOnly);
    return ChartCsvReader::read(buffer);
}

} // namespace

class TestBadCsv : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void refusedWholeWithTheLine_data();
    void refusedWholeWithTheLine();
    void aFileOverTheLimitIsRefusedBeforeReading();
};

void TestBadCsv::initTestCase() {
    const auto r = readBytes(kHead + kRows);
    if (!r)
        QSKIP(qPrintable(QStringLiteral("the minimal chart CSV no longer replays (%1); update "
                                        "tests/badinput/tst_badcsv.cpp")
                             .arg(r.error())));
    QCOMPARE((*r)->rows, 2);
}

void TestBadCsv::refusedWholeWithTheLine_data() {
    QTest::addColumn<QByteArray>("csv");
    QTest::addColumn<QString>("reason");
    const QByteArray t = "2026-01-01T00:00:00.200Z";
    QTest::newRow("empty") << QByteArray() << "empty";
    QTest::newRow("comments only") << QByteArray("# TipScope chart data, format 1\n") << "empty";
    QTest::newRow("header only") << kHead << "no rows";
    QTest::newRow("binary") << QByteArray(256, '\0') << "binary";
    QTest::newRow("Latin-1 degree sign")
        << QByteArray(kHead).replace("\xc2\xb0", "\xb0") + kRows << "not UTF-8";
    QTest::newRow("no header") << kRows << "time";
    QTest::newRow("unknown column")
        << QByteArray(kHead).replace("setpoint", "colour") + kRows << "column 3";
    QTest::newRow("wrong unit") << QByteArray(kHead).replace("tip [\xc2\xb0"
                                                             "C]",
                                                             "tip [K]") +
                                       kRows
                                << "unit";
    QTest::newRow("column twice") << QByteArray(kHead).replace("setpoint", "tip") + kRows
                                  << "twice";
    QByteArray wide = "time";
    for (int i = 0; i < 300; ++i)
        wide += ",port" + QByteArray::number(i + 1) +
                " tip [\xc2\xb0"
                "C]";
    QTest::newRow("300 columns") << wide + "\n"
                                 << "at most";
    QTest::newRow("too few cells") << kHead + kRows + t + ",350\n"
                                   << "line 6";
    QTest::newRow("too many cells") << kHead + kRows + t + ",350,350,,9\n"
                                    << "line 6";
    QTest::newRow("bad time") << kHead + kRows + "yesterday,350,350,\n"
                              << "ISO 8601";
    QTest::newRow("time backwards") << kHead + kRows + "2025-01-01T00:00:00.000Z,350,350,\n"
                                    << "earlier";
    QTest::newRow("text value") << kHead + kRows + t + ",hot,350,\n"
                                << "not a number";
    QTest::newRow("nan") << kHead + kRows + t + ",nan,350,\n"
                         << "not a number";
    QTest::newRow("inf") << kHead + kRows + t + ",inf,350,\n"
                         << "not a number";
    QTest::newRow("1e300") << kHead + kRows + t + ",1e300,350,\n"
                           << "not a number";
    QTest::newRow("decimal comma") << kHead + kRows + t + ",\"350,5\",350,\n"
                                   << "not a number";
    QTest::newRow("half a channel") << kHead + kRows + t + ",350,,\n"
                                    << "not all";
    QTest::newRow("open quote") << kHead + kRows + t + ",\"350,350,\n"
                                << "quoted";
    QTest::newRow("bad event") << kHead + kRows + t + ",350,350,nonsense\n"
                               << "event";
    QTest::newRow("line over 64 kB") << kHead + kRows + t + "," + QByteArray(70000, '3') + ",350,\n"
                                     << "longer than";
    QByteArray comments;
    for (int i = 0; i < 1100; ++i)
        comments += "# note " + QByteArray::number(i) + '\n';
    QTest::newRow("1,100 comment lines") << comments + kHead + kRows << "comment lines";
    QByteArray many = kHead; // 200 rows, about 7 kB
    for (int i = 0; i < 200; ++i)
        many += "2026-01-01T00:00:" + QByteArray::number(10 + i / 10) + '.' +
                QByteArray::number(i % 10) + "00Z,350,350,\n";
    QTest::newRow("NUL after the first 4 kB")
        << many + "2026-01-01T00:01:00.000Z" + QByteArray(",350\0,350,\n", 11) << "binary";
    QTest::newRow("February 30th") << kHead + kRows + "2026-02-30T00:00:00.000Z,350,350,\n"
                                   << "ISO 8601";
}

void TestBadCsv::refusedWholeWithTheLine() {
    QFETCH(QByteArray, csv);
    QFETCH(QString, reason);
    const auto r = readBytes(csv);
    QVERIFY2(!r, "a bad recording was replayed");
    const QString error = r.error();
    QVERIFY2(error.contains(reason, Qt::CaseInsensitive), qPrintable(error.left(300)));
    QVERIFY(error.size() < 2000);
}

void TestBadCsv::aFileOverTheLimitIsRefusedBeforeReading() {
    // A sparse file: over the limit on disk in size, nothing in content, created in no time.
    QTemporaryDir dir;
    QFile f(dir.filePath(QStringLiteral("huge.csv")));
    QVERIFY(f.open(QIODevice::WriteOnly));
    QVERIFY(f.write(kHead + kRows) > 0);
    QVERIFY(f.resize(ChartCsvReader::kMaxFileBytes + 1));
    f.close();
    const auto r = ChartCsvReader::readFile(f.fileName());
    QVERIFY(!r);
    const QString error = r.error();
    QVERIFY2(error.contains(QStringLiteral("MB")), qPrintable(error));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestBadCsv)

} // namespace tst_badcsv
#include "tst_badcsv.moc"
