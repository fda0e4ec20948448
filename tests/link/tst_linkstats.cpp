// LinkStats: the latencies it keeps stay bounded in memory and honest in value (minimum, median,
// percentiles and maximum in order, within what was recorded), the transaction rate counts the
// last five seconds, NAKs add up by code, and a queue's figures match what happened on the wire:
// a latency is never shorter than the device took to answer, nor longer than the whole exchange.
#include "scriptedqueue.h"
#include "testmain.h"

#include "link/linkstats.h"

#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QTest>
#include <algorithm>

namespace tst_linkstats {

using namespace tipscope::link;
using tipscope::protocol::Frame;
using tipscope::test::answerTo;
using tipscope::test::nakTo;
using tipscope::test::ScriptedQueue;

namespace {
constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on
} // namespace

class TestLinkStats : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void nothingRecordedGivesZeroes();
    void theFirstAnswerIsBothMinimumAndMaximum();
    void minimumAndMaximumCoverEveryAnswerEverRecorded();
    void onlyTheLatestLatenciesAreKept();
    void percentilesOfKnownLatencies_data();
    void percentilesOfKnownLatencies();
    void percentilesStayWithinTheRecordedBounds_data();
    void percentilesStayWithinTheRecordedBounds();
    void theRateCountsAnswersOfTheLastFiveSeconds();
    void naksAddUpOverEveryCode();
    void theSummaryNamesEveryFigure();
    void aQueueCountsWhatHappenedOnTheWire();
    void aQueuesLatencyLiesBetweenTheAnswerDelayAndTheWholeExchange();
};

void TestLinkStats::nothingRecordedGivesZeroes() {
    const LinkStats s;
    QCOMPARE(s.medianLatencyUs(), 0);
    QCOMPARE(s.percentileLatencyUs(0.99), 0);
    QCOMPARE(s.transactionsPerSecond(123456), 0.0);
    QCOMPARE(s.nakTotal(), 0);
    QCOMPARE(s.minLatencyUs, 0);
    QCOMPARE(s.maxLatencyUs, 0);
}

void TestLinkStats::theFirstAnswerIsBothMinimumAndMaximum() {
    LinkStats s;
    s.recordAnswer(7000, 0);
    QCOMPARE(s.answered, 1);
    QCOMPARE(s.minLatencyUs, 7000); // not the 0 it started from
    QCOMPARE(s.maxLatencyUs, 7000);
    QCOMPARE(s.medianLatencyUs(), 7000);
}

void TestLinkStats::minimumAndMaximumCoverEveryAnswerEverRecorded() {
    LinkStats s;
    s.recordAnswer(5000, 0);
    s.recordAnswer(3000, 1);
    s.recordAnswer(9000, 2);
    QCOMPARE(s.minLatencyUs, 3000);
    QCOMPARE(s.maxLatencyUs, 9000);
    // Pushed out of the window of recent latencies, the extremes are still the line's.
    for (size_t i = 0; i < 2 * LinkStats::kLatencyWindow; ++i)
        s.recordAnswer(6000, 3 + qint64(i));
    QCOMPARE(s.minLatencyUs, 3000);
    QCOMPARE(s.maxLatencyUs, 9000);
    QCOMPARE(s.medianLatencyUs(), 6000);
    QCOMPARE(s.answered, qint64(3 + 2 * LinkStats::kLatencyWindow));
}

void TestLinkStats::onlyTheLatestLatenciesAreKept() {
    LinkStats s;
    const qint64 n = 20 * LinkStats::kLatencyWindow + 17;
    for (qint64 i = 1; i <= n; ++i)
        s.recordAnswer(i, i);
    QCOMPARE(s.recentLatencyUs.size(), LinkStats::kLatencyWindow);
    QCOMPARE(s.recentLatencyUs.front(), n - qint64(LinkStats::kLatencyWindow) + 1);
    QCOMPARE(s.recentLatencyUs.back(), n);
    // The answer times for the rate are kept for its window only (1 ms apart: 5001 of them).
    QVERIFY2(s.recentAnswerMs.size() <= 5001, qPrintable(QString::number(s.recentAnswerMs.size())));
}

void TestLinkStats::percentilesOfKnownLatencies_data() {
    QTest::addColumn<QList<qint64>>("latencies");
    QTest::addColumn<double>("p");
    QTest::addColumn<qint64>("expected");

    QList<qint64> hundredAndOne;
    for (qint64 i = 1; i <= 101; ++i)
        hundredAndOne.append(i * 1000);
    // Shuffled the same way every run, so the order of arrival cannot matter.
    QList<qint64> shuffled = hundredAndOne;
    std::shuffle(shuffled.begin(), shuffled.end(), QRandomGenerator(15));
    QTest::newRow("median of 1..101 ms") << hundredAndOne << 0.5 << qint64(51000);
    QTest::newRow("median, shuffled") << shuffled << 0.5 << qint64(51000);
    QTest::newRow("0th percentile is the least") << shuffled << 0.0 << qint64(1000);
    QTest::newRow("90th percentile") << shuffled << 0.9 << qint64(91000);
    QTest::newRow("100th percentile is the most") << shuffled << 1.0 << qint64(101000);
    QTest::newRow("one latency") << QList<qint64>{4200} << 0.99 << qint64(4200);
    QTest::newRow("two latencies, median rounds up")
        << QList<qint64>{1000, 3000} << 0.5 << qint64(3000);
}

void TestLinkStats::percentilesOfKnownLatencies() {
    QFETCH(QList<qint64>, latencies);
    QFETCH(double, p);
    QFETCH(qint64, expected);
    LinkStats s;
    for (qint64 l : latencies)
        s.recordAnswer(l, 0);
    QCOMPARE(s.percentileLatencyUs(p), expected);
}

void TestLinkStats::percentilesStayWithinTheRecordedBounds_data() {
    QTest::addColumn<quint32>("seed");
    QTest::addColumn<int>("count");
    for (quint32 seed : {1u, 2u, 3u})
        for (int count : {1, 2, 10, 999, 1000, 1001, 2500})
            QTest::addRow("seed %u, %d answers", seed, count) << seed << count;
}

void TestLinkStats::percentilesStayWithinTheRecordedBounds() {
    QFETCH(quint32, seed);
    QFETCH(int, count);
    QRandomGenerator random(seed);
    LinkStats s;
    for (int i = 0; i < count; ++i)
        s.recordAnswer(random.bounded(1, 2'000'000), i);
    const auto [least, most] =
        std::minmax_element(s.recentLatencyUs.begin(), s.recentLatencyUs.end());
    QCOMPARE(s.percentileLatencyUs(0.0), *least);
    QCOMPARE(s.percentileLatencyUs(1.0), *most);
    qint64 previous = s.minLatencyUs;
    for (double p : {0.0, 0.1, 0.5, 0.9, 0.99, 1.0}) {
        const qint64 v = s.percentileLatencyUs(p);
        QVERIFY2(v >= previous,
                 qPrintable(QStringLiteral("p%1 %2 < %3").arg(p).arg(v).arg(previous)));
        previous = v;
    }
    QVERIFY(previous <= s.maxLatencyUs);
    QVERIFY(s.minLatencyUs <= s.medianLatencyUs());
}

void TestLinkStats::theRateCountsAnswersOfTheLastFiveSeconds() {
    LinkStats s;
    for (qint64 t = 0; t < 10000; t += 100) // 10 a second for 10 s
        s.recordAnswer(1000, t);
    // At 9900 ms the window reaches back to 4900 ms: 51 answers in 5 s.
    QCOMPARE(s.transactionsPerSecond(9900), 51 / 5.0);
    QCOMPARE(s.transactionsPerSecond(12400), 26 / 5.0); // 7400..9900
    QCOMPARE(s.transactionsPerSecond(20000), 0.0);      // a quiet line
}

void TestLinkStats::naksAddUpOverEveryCode() {
    LinkStats s;
    s.naks[1] = 3;
    s.naks[5] = 2;
    s.naks[9] = 1;
    QCOMPARE(s.nakTotal(), 6);
}

void TestLinkStats::theSummaryNamesEveryFigure() {
    LinkStats s;
    s.sent = 12;
    s.timeouts = 3;
    s.corrupted = 4;
    s.stray = 5;
    s.retries = 6;
    s.naks[1] = 2;
    s.recordAnswer(2000, 1000);
    s.recordAnswer(4000, 2000);
    s.recordAnswer(9000, 3000);
    QCOMPARE(s.summary(5000), QStringLiteral("0.6 tx/s, latency 4.0 ms median (2.0-9.0), 12 sent, "
                                             "3 answered, 3 timeouts, 4 corrupted, 2 NAKs, "
                                             "5 stray, 6 retries"));
}

void TestLinkStats::aQueueCountsWhatHappenedOnTheWire() {
    ScriptedQueue line(1, 20);
    // ST1 is answered, MAT refused (NAK 5), TT1 answered only on its second attempt, SMN never.
    qint64 answerBytes = 0;
    line.transport.setResponder([&answerBytes](const Frame &request, int attempt) -> QByteArray {
        QByteArray answer;
        if (request.command == "MAT")
            answer = nakTo(request, 5).encode();
        else if (!(request.command == "TT1" && attempt == 1) && request.command != "SMN")
            answer = answerTo(request, "00350").encode();
        answerBytes += answer.size();
        return answer;
    });
    qint64 writtenBytes = 0;
    connect(&line.transport, &tipscope::test::ScriptedTransport::written, this,
            [&writtenBytes](const QByteArray &bytes) { writtenBytes += bytes.size(); });
    QObject owner;
    QList<Reply *> replies;
    for (const QByteArray command : {"ST1", "MAT", "TT1", "SMN"})
        replies.append(line.queue.enqueue(Request::read(1, command), &owner));
    QTRY_VERIFY_WITH_TIMEOUT(
        std::all_of(replies.begin(), replies.end(), [](Reply *r) { return r->isFinished(); }),
        kWaitMs);

    const LinkStats &s = line.queue.stats();
    QCOMPARE(s.sent, 6); // ST1, MAT, TT1 twice, SMN twice
    QVERIFY(writtenBytes > 6 * 5);
    QCOMPARE(s.sentBytes, writtenBytes);
    QVERIFY(answerBytes > 3 * 5);
    QCOMPARE(s.receivedBytes, answerBytes);
    QCOMPARE(s.answered, 3); // ST1, the NAK, TT1
    QCOMPARE(s.timeouts, 3); // TT1 once, SMN twice
    QCOMPARE(s.retries, 2);  // TT1 and SMN once each
    QCOMPARE(s.naks.value(5), 1);
    QCOMPARE(s.nakTotal(), 1);
    QCOMPARE(s.corrupted, 0);
    QCOMPARE(s.stray, 0);
    QCOMPARE(qint64(s.recentLatencyUs.size()), s.answered);
}

void TestLinkStats::aQueuesLatencyLiesBetweenTheAnswerDelayAndTheWholeExchange() {
    constexpr int kDeviceMs = 30; // how long the device takes to answer
    ScriptedQueue line(2, 500);
    auto &transport = line.transport;
    connect(&transport, &tipscope::test::ScriptedTransport::written, this,
            [&transport](const QByteArray &bytes) {
                // Answered kDeviceMs after the write, and confirmed at once, as a real port does.
                transport.answer(answerTo(*tipscope::protocol::parseFrame(bytes), "00350").encode(),
                                 kDeviceMs);
            });
    QObject owner;
    QElapsedTimer exchange;
    exchange.start();
    Reply *reply = line.queue.enqueue(Request::read(1, "ST1"), &owner);
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kWaitMs);
    const qint64 wholeUs = exchange.nsecsElapsed() / 1000;
    QVERIFY2(reply->ok(), qPrintable(reply->errorString()));

    const LinkStats &s = line.queue.stats();
    QCOMPARE(s.answered, 1);
    QCOMPARE(s.minLatencyUs, s.maxLatencyUs);
    // The reply's own latency runs from its first attempt to its end: never shorter.
    QVERIFY(reply->latencyUs() >= s.minLatencyUs);
    // Bounds, not speeds: the latency includes the device's time and nothing from before the
    // request was queued.
    QVERIFY2(s.minLatencyUs >= kDeviceMs * 1000, qPrintable(QString::number(s.minLatencyUs)));
    QVERIFY2(s.minLatencyUs <= wholeUs,
             qPrintable(QStringLiteral("%1 > %2").arg(s.minLatencyUs).arg(wholeUs)));
    QVERIFY(s.transactionsPerSecond(line.queue.nowMs()) > 0);
}

TIPSCOPE_TEST_MAIN(TestLinkStats)

} // namespace tst_linkstats
#include "tst_linkstats.moc"
