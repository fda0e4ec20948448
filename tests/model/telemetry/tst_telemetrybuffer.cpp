// TelemetryBuffer as a store: the ring keeps the newest samples, refuses what would break time
// order, keeps every value exactly, answers point and raw-window queries, and stays within 16
// bytes per sample per series measured on the real heap.
#include "model/telemetry/telemetrybuffer.h"
#include "testmain.h"

#include <QTest>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace tst_telemetrybuffer {

using namespace tipscope::model;

namespace {

const QStringList kPortSeries = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                 QStringLiteral("power"), QStringLiteral("status")};

#if defined(__GLIBC__)
// Bytes in use on the heap: small blocks from the arenas plus large mmapped ones.
qint64 heapInUse() {
    const struct mallinfo2 info = mallinfo2();
    return qint64(info.uordblks + info.hblkhd);
}
#endif

} // namespace

class TestTelemetryBuffer : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void ringOverwriteKeepsTheNewestCapacitySamples_data();
    void ringOverwriteKeepsTheNewestCapacitySamples();
    void evictedExtremesNeverComeBackAfterWrapAround();
    void olderSampleIsRefusedAndCounted();
    void sampleWithTheWrongNumberOfValuesIsRefusedAndCounted();
    void valueAtGivesTheSampleAtOrJustBeforeTheTime_data();
    void valueAtGivesTheSampleAtOrJustBeforeTheTime();
    void valuesBeyondSixteenBitsAreKeptExactly();
    void nothingIsReadInAGapAndTheNextSampleEndsIt();
    void aWindowSplitsIntoTheStretchesBetweenItsGaps();
    void gapsOlderThanTheOldestSampleAreDropped();
    void unknownSeriesGivesEmptyAnswers();
    void memoryPerSamplePerSeriesIsAtMostSixteenBytes_data();
    void memoryPerSamplePerSeriesIsAtMostSixteenBytes();
    void emptyBufferAllocatesNoSampleStorage();
};

void TestTelemetryBuffer::ringOverwriteKeepsTheNewestCapacitySamples_data() {
    QTest::addColumn<int>("capacity");
    QTest::addColumn<int>("appended");

    QTest::newRow("not full") << 1000 << 999;
    QTest::newRow("exactly full") << 1000 << 1000;
    QTest::newRow("one overwritten") << 1000 << 1001;
    QTest::newRow("wrapped two and a half times") << 1000 << 2500;
    QTest::newRow("capacity of one") << 1 << 5;
}

void TestTelemetryBuffer::ringOverwriteKeepsTheNewestCapacitySamples() {
    QFETCH(int, capacity);
    QFETCH(int, appended);
    TelemetryBuffer buffer({QStringLiteral("tip"), QStringLiteral("power")}, capacity);
    for (int i = 0; i < appended; ++i)
        QCOMPARE(buffer.append(i * 10, {i, -i}), AppendResult::Accepted);

    const int kept = qMin(capacity, appended);
    const int oldest = appended - kept;
    QCOMPARE(buffer.capacity(), capacity);
    QCOMPARE(buffer.size(), kept);
    QCOMPARE(buffer.totalAppended(), appended);
    QCOMPARE(buffer.firstTime(), oldest * 10);
    QCOMPARE(buffer.lastTime(), (appended - 1) * 10);

    const QList<TelemetryBuffer::Sample> power = buffer.samples(1, 0, appended * 10);
    QCOMPARE(power.size(), kept);
    for (int i = 0; i < kept; ++i) {
        QCOMPARE(power[i].timeMs, (oldest + i) * 10);
        QCOMPARE(power[i].value, -(oldest + i));
    }
    const TelemetryBuffer::Stats tip = buffer.windowStats(0, 0, appended * 10);
    QCOMPARE(tip.count, kept);
    QCOMPARE(tip.min, oldest);
    QCOMPARE(tip.max, appended - 1);
}

// The block holding the oldest samples has lost some to the ring; its summary still remembers
// them, so it must never be used whole again.
void TestTelemetryBuffer::evictedExtremesNeverComeBackAfterWrapAround() {
    const int capacity = 4096;
    TelemetryBuffer buffer({QStringLiteral("tip")}, capacity);
    buffer.append(0, {9999});  // evicted below
    buffer.append(1, {-9999}); // evicted below
    for (int i = 2; i < capacity + 2; ++i)
        buffer.append(i, {i % 7});

    QCOMPARE(buffer.firstTime(), 2);
    const TelemetryBuffer::Stats stats = buffer.windowStats(0, 0, capacity + 2);
    QCOMPARE(stats.min, 0);
    QCOMPARE(stats.max, 6);
    for (int buckets : {1, 3, 64, 1920}) {
        for (const MinMaxBucket &b : buffer.decimate(0, 0, capacity + 2, buckets)) {
            QVERIFY(b.min >= 0);
            QVERIFY(b.max <= 6);
        }
    }
}

void TestTelemetryBuffer::olderSampleIsRefusedAndCounted() {
    TelemetryBuffer buffer({QStringLiteral("tip")}, 100);
    QCOMPARE(buffer.append(1000, {300}), AppendResult::Accepted);
    QCOMPARE(buffer.append(999, {301}), AppendResult::OutOfOrder);
    QCOMPARE(buffer.append(1000, {302}), AppendResult::Accepted); // same time is in order
    QCOMPARE(buffer.append(500, {303}), AppendResult::OutOfOrder);

    QCOMPARE(buffer.outOfOrderCount(), 2);
    QCOMPARE(buffer.size(), 2);
    QCOMPARE(buffer.lastTime(), 1000);
    QCOMPARE(buffer.valueAt(0, 1000)->value, 302);
    QCOMPARE(buffer.windowStats(0, 0, 2000).max, 302);
}

void TestTelemetryBuffer::sampleWithTheWrongNumberOfValuesIsRefusedAndCounted() {
    TelemetryBuffer buffer(kPortSeries, 100);
    QCOMPARE(buffer.append(1, {1, 2, 3}), AppendResult::WrongValueCount);
    QCOMPARE(buffer.append(2, {1, 2, 3, 4, 5}), AppendResult::WrongValueCount);
    QCOMPARE(buffer.append(3, {1, 2, 3, 4}), AppendResult::Accepted);
    QCOMPARE(buffer.malformedCount(), 2);
    QCOMPARE(buffer.outOfOrderCount(), 0);
    QCOMPARE(buffer.size(), 1);
}

void TestTelemetryBuffer::valueAtGivesTheSampleAtOrJustBeforeTheTime_data() {
    QTest::addColumn<qint64>("time");
    QTest::addColumn<bool>("found");
    QTest::addColumn<qint64>("sampleTime");
    QTest::addColumn<qint32>("value");

    // Held (after wrap-around): 300 -> 3, 400 -> 4, 400 -> 40, 500 -> 5.
    QTest::newRow("before the oldest held") << qint64(299) << false << qint64(0) << 0;
    QTest::newRow("overwritten time") << qint64(200) << false << qint64(0) << 0;
    QTest::newRow("exactly the oldest") << qint64(300) << true << qint64(300) << 3;
    QTest::newRow("between samples") << qint64(399) << true << qint64(300) << 3;
    QTest::newRow("repeated time gives the newer") << qint64(400) << true << qint64(400) << 40;
    QTest::newRow("exactly the newest") << qint64(500) << true << qint64(500) << 5;
    QTest::newRow("after the newest") << qint64(10'000) << true << qint64(500) << 5;
}

void TestTelemetryBuffer::valueAtGivesTheSampleAtOrJustBeforeTheTime() {
    QFETCH(qint64, time);
    QFETCH(bool, found);
    QFETCH(qint64, sampleTime);
    QFETCH(qint32, value);
    TelemetryBuffer buffer({QStringLiteral("tip")}, 4);
    for (const auto &[t, v] :
         {std::pair{100, 1}, {200, 2}, {300, 3}, {400, 4}, {400, 40}, {500, 5}})
        buffer.append(t, {v});

    const std::optional<TelemetryBuffer::Sample> sample = buffer.valueAt(0, time);
    QCOMPARE(sample.has_value(), found);
    if (found) {
        QCOMPARE(sample->timeMs, sampleTime);
        QCOMPARE(sample->value, value);
    }
}

void TestTelemetryBuffer::valuesBeyondSixteenBitsAreKeptExactly() {
    TelemetryBuffer buffer({QStringLiteral("small"), QStringLiteral("big")}, 300);
    const qint32 big = 2'000'000'000;
    for (int i = 0; i < 500; ++i)
        buffer.append(i, {i % 100, i == 250 ? -big : i == 400 ? big : i});

    QCOMPARE(buffer.valueAt(1, 250)->value, -big);
    QCOMPARE(buffer.valueAt(1, 400)->value, big);
    QCOMPARE(buffer.valueAt(1, 499)->value, 499);
    QCOMPARE(buffer.valueAt(0, 499)->value, 99);
    const TelemetryBuffer::Stats stats = buffer.windowStats(1, 0, 500);
    QCOMPARE(stats.min, -big);
    QCOMPARE(stats.max, big);
    QCOMPARE(stats.count, 300);
}

void TestTelemetryBuffer::unknownSeriesGivesEmptyAnswers() {
    TelemetryBuffer buffer(kPortSeries, 100);
    buffer.append(1, {1, 2, 3, 4});
    QCOMPARE(buffer.seriesIndex(QStringLiteral("power")), 2);
    QCOMPARE(buffer.seriesIndex(QStringLiteral("flow")), -1);
    QVERIFY(!buffer.valueAt(-1, 1));
    QVERIFY(!buffer.valueAt(4, 1));
    QVERIFY(buffer.samples(4, 0, 10).isEmpty());
    QVERIFY(buffer.decimate(-1, 0, 10, 5).isEmpty());
    QCOMPARE(buffer.windowStats(4, 0, 10).count, 0);
}

void TestTelemetryBuffer::memoryPerSamplePerSeriesIsAtMostSixteenBytes_data() {
    QTest::addColumn<QStringList>("series");
    QTest::addColumn<qint32>("amplitude");

    QTest::newRow("four 16-bit series, a day at 10 Hz") << kPortSeries << 1000;
    QTest::newRow("one series widened to 32 bits") << QStringList{QStringLiteral("x")} << 100'000;
}

void TestTelemetryBuffer::memoryPerSamplePerSeriesIsAtMostSixteenBytes() {
#if !defined(__GLIBC__)
    QSKIP("measuring the heap needs glibc's mallinfo2()");
#else
    QFETCH(QStringList, series);
    QFETCH(qint32, amplitude);
    const int capacity = TelemetryBuffer::kDefaultCapacity;
    const QList<qint32> values(series.size(), 0);

    const qint64 before = heapInUse();
    auto buffer = std::make_unique<TelemetryBuffer>(series, capacity);
    QList<qint32> sample = values;
    for (int i = 0; i < capacity; ++i) {
        sample.fill(i % 2 ? amplitude : -amplitude);
        buffer->append(qint64(i) * 100, sample);
    }
    const qint64 heap = heapInUse() - before;

    const double perSamplePerSeries = double(heap) / (double(capacity) * double(series.size()));
    qInfo("heap %lld bytes, %.2f bytes per sample per series; buffer reports %lld, %.2f", heap,
          perSamplePerSeries, buffer->memoryBytes(), buffer->bytesPerSamplePerSeries());
    QVERIFY(perSamplePerSeries <= 16.0);
    QVERIFY(buffer->bytesPerSamplePerSeries() <= 16.0);
    // The report is the real allocation, give or take allocator bookkeeping.
    QVERIFY(qAbs(buffer->memoryBytes() - heap) < heap / 100 + 4096);
#endif
}

void TestTelemetryBuffer::emptyBufferAllocatesNoSampleStorage() {
    const TelemetryBuffer buffer(kPortSeries);
    QCOMPARE(buffer.capacity(), TelemetryBuffer::kDefaultCapacity);
    QVERIFY(buffer.isEmpty());
    QCOMPARE(buffer.firstTime(), 0);
    QCOMPARE(buffer.lastTime(), 0);
    QVERIFY(buffer.memoryBytes() < 1024);
    QVERIFY(!buffer.valueAt(0, 0));
    QVERIFY(buffer.samples(0, 0, 1).isEmpty());
}

void TestTelemetryBuffer::nothingIsReadInAGapAndTheNextSampleEndsIt() {
    TelemetryBuffer buffer(kPortSeries);
    buffer.append(1000, {300, 350, 0, 0});
    buffer.markGap(1500, TelemetryGap::Cause::LineDown);
    buffer.markGap(2000, TelemetryGap::Cause::NoAnswer); // one gap: the first cause stays
    QVERIFY(buffer.gaps().isOpen());
    QCOMPARE(buffer.valueAt(0, 1000)->value, 300); // the last sample before it stays readable
    QCOMPARE(buffer.valueAt(0, 1400)->value, 300);
    QVERIFY(!buffer.valueAt(0, 1500));
    QVERIFY(!buffer.valueAt(0, 99'000)); // still open: nothing known up to now
    buffer.append(26'500, {340, 350, 0, 0});
    QVERIFY(!buffer.gaps().isOpen());
    QCOMPARE(buffer.gaps().size(), 1);
    const TelemetryGap gap = *buffer.gaps().at(20'000);
    QCOMPARE(gap.startMs, 1500);
    QCOMPARE(gap.endMs, std::optional<qint64>(26'500));
    QCOMPARE(gap.cause, TelemetryGap::Cause::LineDown);
    QVERIFY(!buffer.valueAt(0, 26'499));
    QCOMPARE(buffer.valueAt(0, 26'500)->value, 340);
    QCOMPARE(buffer.valueAt(0, 30'000)->value, 340);
}

void TestTelemetryBuffer::aWindowSplitsIntoTheStretchesBetweenItsGaps() {
    TelemetryBuffer buffer(kPortSeries);
    buffer.append(0, {1, 1, 1, 1});
    buffer.markGap(100, TelemetryGap::Cause::LineDown);
    buffer.append(200, {1, 1, 1, 1});
    buffer.markGap(300, TelemetryGap::Cause::Disconnected);
    buffer.append(400, {1, 1, 1, 1});
    using Stretch = QPair<qint64, qint64>;
    QCOMPARE(buffer.gaps().continuousStretches(0, 1000),
             (QList<Stretch>{{0, 100}, {200, 300}, {400, 1000}}));
    QCOMPARE(buffer.gaps().continuousStretches(150, 350), (QList<Stretch>{{200, 300}}));
    QCOMPARE(buffer.gaps().within(250, 1000).size(), 1);
    buffer.markGap(500, TelemetryGap::Cause::NoAnswer); // an open gap ends the last stretch
    QCOMPARE(buffer.gaps().continuousStretches(400, 1000), (QList<Stretch>{{400, 500}}));
}

void TestTelemetryBuffer::gapsOlderThanTheOldestSampleAreDropped() {
    TelemetryBuffer buffer(kPortSeries, 4);
    buffer.append(0, {1, 1, 1, 1});
    buffer.markGap(10, TelemetryGap::Cause::LineDown);
    for (int i = 1; i <= 4; ++i)
        buffer.append(100 * i, {1, 1, 1, 1});
    QCOMPARE(buffer.gaps().size(), 1); // it ends at 100, still held
    buffer.append(500, {1, 1, 1, 1});  // 100 leaves the ring, the gap goes with it
    QCOMPARE(buffer.gaps().size(), 0);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestTelemetryBuffer)

} // namespace tst_telemetrybuffer
#include "tst_telemetrybuffer.moc"
