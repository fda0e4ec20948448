// ChartCsvParser, the chart CSV as a stream: fed whole, a byte at a time or in odd chunks, a file
// gives the same recording (lines split anywhere, a last line without a line break); what it
// holds grows with what it took; the comment lines are bounded; and a problem names its line.
// The formats' own rules (columns, units, times, events) are tst_chartscsv's, through the reader.
#include "model/recording/chartcsvparser.h"
#include "testmain.h"

#include <QTest>

namespace tst_chartcsvparser {

using namespace tipscope::model;

namespace {

const QByteArray kFile = "# TipScope chart data, format 1\n"
                         "time,port1 tip [°C],port1 setpoint [°C],events\n"
                         "2023-11-14T22:13:20.000Z,350,350,\n"
                         "2023-11-14T22:13:20.100Z,341,350,port1 status: Working → Stand\n"
                         "2023-11-14T22:13:20.200Z,333,350,\n"
                         "2023-11-14T22:13:20.300Z,330,350,"; // no line break at the end
constexpr qint64 kFirstMs = 1'700'000'000'000;

// The recording parsed from `file` fed in chunks of `chunk` bytes (0: whole), as text to compare.
QString parsed(const QByteArray &file, qsizetype chunk, QString *error = nullptr) {
    ChartCsvParser parser;
    const qsizetype step = chunk > 0 ? chunk : file.size();
    bool ok = true;
    for (qsizetype at = 0; ok && at < file.size(); at += step)
        ok = parser.feed(file.constData() + at, qMin(step, file.size() - at));
    ok = ok && parser.finish();
    if (error)
        *error = parser.error();
    if (!ok)
        return {};
    ChartRecordingData data = parser.take();
    QStringList out;
    for (qsizetype c = 0; c < data.recording->channels.size(); ++c) {
        const TelemetryBuffer &b = data.buffers.at(size_t(c));
        out << QStringLiteral("%1: %2 samples")
                   .arg(data.recording->channels.at(c).id)
                   .arg(b.totalAppended());
        for (int s = 0; s < b.seriesCount(); ++s)
            for (const TelemetrySample &sample : b.samples(s, kFirstMs, kFirstMs + 1000))
                out << QStringLiteral("%1 %2 %3")
                           .arg(b.seriesNames().at(s))
                           .arg(sample.timeMs - kFirstMs)
                           .arg(sample.value);
    }
    out << QStringLiteral("%1 event(s)").arg(data.recording->events.size());
    return out.join(QLatin1Char('\n'));
}

} // namespace

class TestChartCsvParser : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void anyChunkingGivesTheSameRecording_data();
    void anyChunkingGivesTheSameRecording();
    void whatItHoldsGrowsWithWhatItTook();
    void commentLinesAreBounded();
    void aProblemNamesItsLine();
};

void TestChartCsvParser::anyChunkingGivesTheSameRecording_data() {
    QTest::addColumn<int>("chunk");
    QTest::newRow("a byte at a time") << 1;
    QTest::newRow("seven bytes") << 7;
    QTest::newRow("splitting the arrow's UTF-8") << 86; // bytes 170-172: 172 is a chunk's first
    QTest::newRow("a line and a half") << 52;
}

void TestChartCsvParser::anyChunkingGivesTheSameRecording() {
    QFETCH(int, chunk);
    const QString whole = parsed(kFile, 0);
    QVERIFY2(whole.startsWith(QStringLiteral("port1: 4 samples")), qPrintable(whole));
    QVERIFY2(whole.contains(QStringLiteral("tip 300 330")), qPrintable(whole)); // the last line
    QVERIFY2(whole.endsWith(QStringLiteral("1 event(s)")), qPrintable(whole));
    QCOMPARE(parsed(kFile, chunk), whole);
}

void TestChartCsvParser::whatItHoldsGrowsWithWhatItTook() {
    ChartCsvParser parser;
    const qsizetype header = kFile.indexOf("2023");
    QVERIFY(parser.feed(kFile.constData(), header));
    const qint64 headerOnly = parser.heldBytes();
    QVERIFY(parser.feed(kFile.constData() + header, kFile.size() - header));
    QVERIFY(parser.finish());
    QVERIFY2(parser.heldBytes() > headerOnly,
             qPrintable(QStringLiteral("%1 after the header, %2 after the rows")
                            .arg(headerOnly)
                            .arg(parser.heldBytes())));
}

void TestChartCsvParser::commentLinesAreBounded() {
    QByteArray comments;
    for (int i = 0; i <= ChartCsvReader::kMaxCommentLines; ++i)
        comments += "# a note\n";
    QString error;
    QVERIFY(parsed(comments + kFile, 0, &error).isEmpty());
    QVERIFY2(
        error.startsWith(QStringLiteral("line %1: ").arg(ChartCsvReader::kMaxCommentLines + 1)) &&
            error.contains(QStringLiteral("comment lines")),
        qPrintable(error));
}

void TestChartCsvParser::aProblemNamesItsLine() {
    QString error;
    QVERIFY(parsed(kFile + "\n2023-11-14T22:13:20.400Z,hot,350,\n", 5, &error).isEmpty());
    QVERIFY2(error.startsWith(QStringLiteral("line 7: ")), qPrintable(error));
    ChartCsvParser parser;
    QVERIFY(!parser.fail(QStringLiteral("before any line")));
    QCOMPARE(parser.error(), QStringLiteral("before any line"));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestChartCsvParser)

} // namespace tst_chartcsvparser

#include "tst_chartcsvparser.moc"
