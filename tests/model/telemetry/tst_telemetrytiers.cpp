// A tiered TelemetryBuffer against a single-tier one fed the same samples: the full-rate tier
// keeps the boundary, older samples fold into per-bucket summaries that give the same min and max
// per chart column and the same window statistics, gaps stay gaps (in the data and on the
// chart), exact samples are only offered where they exist, and the older tier keeps its budget.
#include "model/chart/chartframe.h"
#include "model/telemetry/telemetry.h"
#include "model/telemetry/telemetrybuffer.h"
#include "telemetryreference.h"
#include "testmain.h"

#include <QTest>
#include <cmath>

namespace tst_telemetrytiers {

using namespace tipscope::model;
using tipscope::model::test::SampleGenerator;

namespace {

constexpr qint64 kSecond = 1000;
constexpr qint64 kMinute = 60 * kSecond;
const QStringList kSeries = {QStringLiteral("tip"), QStringLiteral("power")};

qint64 alignDown(qint64 t, qint64 step) {
    return t / step * step - (t % step < 0 ? step : 0);
}

TelemetryTiers tiers(qint64 fullRateMs, qint64 historyMs, qint64 bucketMs) {
    TelemetryTiers t;
    t.fullRateMs = fullRateMs;
    t.historyMs = historyMs;
    t.bucketMs = bucketMs;
    return t;
}

// Random telemetry into both buffers; one pause in three is a gap (the line went down).
void feed(TelemetryBuffer &tiered, TelemetryBuffer &flat, SampleGenerator &g, int count) {
    for (int i = 0; i < count; ++i) {
        const qint64 last = flat.lastTime();
        const qint64 time = g.nextTime();
        if (i > 0 && time - last > kSecond && g.pick(0, 2) == 0) {
            const qint64 at = last + g.pick(1, 500);
            tiered.markGap(at, TelemetryGap::Cause::LineDown);
            flat.markGap(at, TelemetryGap::Cause::LineDown);
        }
        const QList<qint32> values = g.nextValues();
        QCOMPARE(tiered.append(time, values), AppendResult::Accepted);
        QCOMPARE(flat.append(time, values), AppendResult::Accepted);
    }
}

void feedSteady(TelemetryBuffer &buffer, qint64 from, qint64 to, qint64 stepMs) {
    for (qint64 t = from; t < to; t += stepMs)
        buffer.append(t, {qint32(t / stepMs % 1000), qint32(t / stepMs % 7)});
}

} // namespace

class TestTelemetryTiers : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void histories_data();
    void columnsOnBucketEdgesMatchTheUntieredBufferAcrossTheBoundary_data() { histories_data(); }
    void columnsOnBucketEdgesMatchTheUntieredBufferAcrossTheBoundary();
    void chartColumnsLoseNoSpikeAndInventNone_data() { histories_data(); }
    void chartColumnsLoseNoSpikeAndInventNone();
    void windowStatsOnBucketEdgesMatchTheUntieredBuffer_data() { histories_data(); }
    void windowStatsOnBucketEdgesMatchTheUntieredBuffer();
    void fullRateTierGrowsToTheBoundaryThenFolds();
    void aGapStaysAGapInTheOlderTier();
    void theChartBreaksItsCurveAtAGapInTheOlderTier();
    void valueAtInTheOlderTierGivesTheFirstSampleOfItsBucket();
    void samplesGivesOnlyTheFullRateTier();
    void olderTierKeepsItsBudgetAndDropsTheOldestSummaries();
    void telemetryMakesTieredBuffersUnlessToldACapacity();
};

void TestTelemetryTiers::histories_data() {
    QTest::addColumn<quint32>("seed");
    QTest::addColumn<bool>("wide");
    QTest::addColumn<qint64>("bucketMs");

    QTest::newRow("1 s buckets") << 1u << false << kSecond;
    QTest::newRow("5 s buckets") << 2u << false << 5 * kSecond;
    // Values near the 32-bit limits: every sum overflows, so buckets split into single samples.
    QTest::newRow("wide values") << 3u << true << 2 * kSecond;
}

namespace {

struct Pair {
    TelemetryBuffer tiered;
    TelemetryBuffer flat;
};

// About 11 hours of random history with its pauses and gaps, the newest hour at full rate.
Pair filledPair(quint32 seed, bool wide, qint64 bucketMs) {
    constexpr int kSamples = 100000;
    Pair p{TelemetryBuffer(kSeries, tiers(60 * kMinute, 48 * 60 * kMinute, bucketMs)),
           TelemetryBuffer(kSeries, kSamples)};
    SampleGenerator g(seed, int(kSeries.size()), wide);
    feed(p.tiered, p.flat, g, kSamples);
    return p;
}

} // namespace

void TestTelemetryTiers::columnsOnBucketEdgesMatchTheUntieredBufferAcrossTheBoundary() {
    QFETCH(quint32, seed);
    QFETCH(bool, wide);
    QFETCH(qint64, bucketMs);
    const Pair p = filledPair(seed, wide, bucketMs);
    QVERIFY(p.tiered.summaryCount() > 0);
    QCOMPARE(p.tiered.firstTime(), p.flat.firstTime());
    const qint64 boundary = p.tiered.fullRateFrom();
    QVERIFY(boundary > p.flat.firstTime());

    SampleGenerator g(seed + 100, 1, false);
    for (int columns : {1920, 800, 333, 7}) {
        for (int round = 0; round < 8; ++round) {
            const qint64 width = bucketMs * g.pick(1, 40);
            const qint64 span = width * columns;
            // A window with the boundary somewhere inside it.
            const qint64 t0 = alignDown(boundary - span * g.pick(1, 99) / 100, bucketMs);
            const qint64 t1 = t0 + span;
            for (int series = 0; series < kSeries.size(); ++series) {
                const QList<MinMaxBucket> got = p.tiered.decimate(series, t0, t1, columns);
                const QList<MinMaxBucket> want = p.flat.decimate(series, t0, t1, columns);
                QCOMPARE(got.size(), want.size());
                for (qsizetype k = 0; k < got.size(); ++k) {
                    const MinMaxBucket &a = got.at(k);
                    const MinMaxBucket &b = want.at(k);
                    QCOMPARE(a.startMs, b.startMs);
                    QCOMPARE(a.min, b.min);
                    QCOMPARE(a.max, b.max);
                    QCOMPARE(a.count, b.count);
                    // Dated at their bucket's first sample: never later, less than a bucket early.
                    QVERIFY(a.minTimeMs <= b.minTimeMs && b.minTimeMs - a.minTimeMs < bucketMs);
                    QVERIFY(a.maxTimeMs <= b.maxTimeMs && b.maxTimeMs - a.maxTimeMs < bucketMs);
                }
            }
        }
    }
}

// Columns that do not fall on bucket edges (any window a person scrolls to): a bucket
// straddling an edge counts in the column it starts in, so each column holds only values from
// itself and the bucket after its end, and each untiered column's extremes show up in the same
// column or the one before.
void TestTelemetryTiers::chartColumnsLoseNoSpikeAndInventNone() {
    QFETCH(quint32, seed);
    QFETCH(bool, wide);
    QFETCH(qint64, bucketMs);
    const Pair p = filledPair(seed, wide, bucketMs);
    const qint64 boundary = p.tiered.fullRateFrom();
    SampleGenerator g(seed + 200, 1, false);
    constexpr int kColumns = 1920;
    for (int round = 0; round < 6; ++round) {
        const qint64 span = qint64(kColumns) * bucketMs * g.pick(2, 30) + g.pick(0, 999);
        const qint64 t0 = boundary - span * g.pick(1, 99) / 100 + g.pick(0, 999);
        const qint64 t1 = t0 + span;
        // Chart edges: whole buckets starting in the window, so the envelope holds every
        // sample of the window's whole buckets and nothing beyond a bucket after it.
        qint32 low = std::numeric_limits<qint32>::max();
        qint32 high = std::numeric_limits<qint32>::min();
        // Kept whole: a range-for over .at(0) of the temporary would read freed columns.
        const auto columns = p.tiered.decimate({0}, t0, t1, kColumns, ColumnEdges::Blocks);
        for (const MinMaxBucket &b : columns.at(0)) {
            low = qMin(low, b.min);
            high = qMax(high, b.max);
        }
        const TelemetryBuffer::Stats outer = p.flat.windowStats(0, t0, t1 + bucketMs);
        const TelemetryBuffer::Stats inner =
            p.flat.windowStats(0, alignDown(t0 + bucketMs - 1, bucketMs), alignDown(t1, bucketMs));
        QVERIFY(low >= outer.min && high <= outer.max);
        QVERIFY(low <= inner.min && high >= inner.max);

        // Exact edges, column by column.
        const QList<MinMaxBucket> got = p.tiered.decimate(0, t0, t1, kColumns);
        const QList<MinMaxBucket> want = p.flat.decimate(0, t0, t1, kColumns);
        QHash<qint64, MinMaxBucket> byStart;
        for (const MinMaxBucket &b : got)
            byStart.insert(b.startMs, b);
        for (qsizetype k = 0; k < got.size(); ++k) {
            const MinMaxBucket &b = got.at(k);
            const qint64 end = k + 1 < got.size() ? got.at(k + 1).startMs : t1;
            const TelemetryBuffer::Stats around = p.flat.windowStats(0, b.startMs, end + bucketMs);
            QVERIFY(b.min >= around.min);
            QVERIFY(b.max <= around.max);
        }
        const qint64 columnWidth = span / kColumns;
        for (const MinMaxBucket &b : want) {
            // Samples in a bucket that started before t0 are the only ones not drawn.
            if (b.startMs == t0)
                continue;
            qint32 columnLow = std::numeric_limits<qint32>::max();
            qint32 columnHigh = std::numeric_limits<qint32>::min();
            for (qint64 start : {b.startMs - columnWidth - 1, b.startMs - columnWidth, b.startMs}) {
                if (const auto it = byStart.constFind(start); it != byStart.constEnd()) {
                    columnLow = qMin(columnLow, it->min);
                    columnHigh = qMax(columnHigh, it->max);
                }
            }
            QVERIFY2(columnLow <= b.min && columnHigh >= b.max,
                     qPrintable(QString::number(b.startMs)));
        }
    }
}

void TestTelemetryTiers::windowStatsOnBucketEdgesMatchTheUntieredBuffer() {
    QFETCH(quint32, seed);
    QFETCH(bool, wide);
    QFETCH(qint64, bucketMs);
    const Pair p = filledPair(seed, wide, bucketMs);
    const qint64 boundary = p.tiered.fullRateFrom();
    SampleGenerator g(seed + 300, 1, false);
    for (int round = 0; round < 30; ++round) {
        const qint64 t0 = alignDown(boundary - bucketMs * g.pick(1, 20000), bucketMs);
        const qint64 t1 = alignDown(boundary + bucketMs * g.pick(-10000, 20000), bucketMs);
        for (int series = 0; series < kSeries.size(); ++series) {
            const TelemetryBuffer::Stats got = p.tiered.windowStats(series, t0, t1);
            const TelemetryBuffer::Stats want = p.flat.windowStats(series, t0, t1);
            QCOMPARE(got.count, want.count);
            QCOMPARE(got.min, want.min);
            QCOMPARE(got.max, want.max);
            QCOMPARE(got.mean, want.mean);
        }
    }
}

void TestTelemetryTiers::fullRateTierGrowsToTheBoundaryThenFolds() {
    TelemetryBuffer buffer(kSeries, tiers(10 * kMinute, 60 * kMinute, kSecond));
    const int startCapacity = buffer.capacity();
    feedSteady(buffer, 0, 45 * kMinute, 100);
    const qint64 last = buffer.lastTime();
    QVERIFY(buffer.capacity() > startCapacity);
    QVERIFY(buffer.summaryCount() > 0);
    // Every sample of the boundary is held as it came, and not much more than that.
    QVERIFY(buffer.fullRateFrom() <= last - 10 * kMinute);
    QVERIFY(buffer.fullRateFrom() >= last - 13 * kMinute);
    QCOMPARE(buffer.samples(0, buffer.fullRateFrom(), last + 1).size(), buffer.size());
    QCOMPARE(buffer.firstTime(), qint64(0));
    QCOMPARE(buffer.totalAppended(), 45 * kMinute / 100);
    // Each summary is one second of ten samples.
    const TelemetryBuffer::Stats all = buffer.windowStats(0, 0, last + 1);
    QCOMPARE(all.count, buffer.totalAppended());
    QCOMPARE(buffer.summaryCount(), int(buffer.fullRateFrom() / kSecond));
}

// The line goes down twice: once within a bucket (the bucket splits at the gap), once for a
// minute. Both gaps survive the fold; nothing is read in them.
void TestTelemetryTiers::aGapStaysAGapInTheOlderTier() {
    TelemetryBuffer tiered(kSeries, tiers(kMinute, 60 * kMinute, kSecond));
    TelemetryBuffer flat(kSeries, 100000);
    const auto both = [&](auto &&f) {
        f(tiered);
        f(flat);
    };
    both([](TelemetryBuffer &b) {
        feedSteady(b, 0, 300000, 100);
        b.markGap(299950, TelemetryGap::Cause::LineDown);
        feedSteady(b, 299980, 400000, 100);
        b.markGap(400000, TelemetryGap::Cause::NoAnswer);
        feedSteady(b, 460000, 20 * kMinute, 100);
    });
    QVERIFY(tiered.fullRateFrom() > 460000);
    const QList<TelemetryGap> gaps = tiered.gaps().within(0, 20 * kMinute);
    QCOMPARE(gaps.size(), 2);
    QCOMPARE(gaps.at(0).startMs, qint64(299950));
    QCOMPARE(*gaps.at(0).endMs, qint64(299980));
    QCOMPARE(*gaps.at(1).endMs, qint64(460000));
    QVERIFY(!tiered.valueAt(0, 299960));
    QVERIFY(!tiered.valueAt(0, 430000));
    // The bucket [299 s, 300 s) is two summaries: before the gap, and from its end on.
    QCOMPARE(tiered.valueAt(0, 299940)->timeMs, qint64(299000));
    QCOMPARE(tiered.valueAt(0, 299990)->timeMs, qint64(299980));
    const QList<MinMaxBucket> columns = tiered.decimate(0, 299000, 300000, 100);
    QCOMPARE(columns.size(), 2);
    QCOMPARE(columns.at(0).count, 10);
    QCOMPARE(columns.at(1).startMs, qint64(299980));
    QCOMPARE(columns.at(1).count, 1);
    // Nothing in the long gap, on any grid.
    for (const MinMaxBucket &b : tiered.decimate(0, 390000, 470000, 800))
        QVERIFY(b.startMs < 400000 || b.startMs >= 460000);
    // One-second columns: the same as every sample would give.
    const QList<MinMaxBucket> got = tiered.decimate(0, 0, 20 * kMinute, 1200);
    const QList<MinMaxBucket> want = flat.decimate(0, 0, 20 * kMinute, 1200);
    QCOMPARE(got.size(), want.size());
    for (qsizetype k = 0; k < got.size(); ++k) {
        QCOMPARE(got.at(k).min, want.at(k).min);
        QCOMPARE(got.at(k).max, want.at(k).max);
        QCOMPARE(got.at(k).count, want.at(k).count);
    }
}

void TestTelemetryTiers::theChartBreaksItsCurveAtAGapInTheOlderTier() {
    TelemetryBuffer buffer(kSeries, tiers(kMinute, 60 * kMinute, kSecond));
    feedSteady(buffer, 0, 400000, 100);
    buffer.markGap(400000, TelemetryGap::Cause::LineDown);
    feedSteady(buffer, 460000, 20 * kMinute, 100);
    QVERIFY(buffer.fullRateFrom() > 460000);
    SeriesFormat format;
    const QList<QPointF> points = minMaxPoints(buffer, 0, 0, 20 * kMinute, 300, format, nullptr);
    qsizetype breaks = 0;
    for (qsizetype i = 0; i < points.size(); ++i) {
        if (!std::isnan(points.at(i).y()))
            continue;
        ++breaks;
        QVERIFY(points.at(i - 1).x() < 400000);
        QVERIFY(points.at(i + 1).x() >= 460000);
    }
    QCOMPARE(breaks, 1);
}

// The newest summary at or before the time stands for it, by its first sample (a real one).
void TestTelemetryTiers::valueAtInTheOlderTierGivesTheFirstSampleOfItsBucket() {
    TelemetryBuffer tiered(kSeries, tiers(kMinute, 60 * kMinute, 5 * kSecond));
    TelemetryBuffer flat(kSeries, 100000);
    for (TelemetryBuffer *b : {&tiered, &flat})
        feedSteady(*b, 130, 10 * kMinute, 250);
    QVERIFY(tiered.fullRateFrom() > 123456);
    for (qint64 t : {qint64(130), qint64(4999), qint64(5000), qint64(123456)}) {
        const qint64 bucketStart = alignDown(flat.valueAt(1, t)->timeMs, 5 * kSecond);
        const TelemetryBuffer::Sample first =
            flat.samples(1, bucketStart, bucketStart + 5 * kSecond).first();
        const auto got = tiered.valueAt(1, t);
        QVERIFY(got);
        QCOMPARE(got->timeMs, first.timeMs);
        QCOMPARE(got->value, first.value);
    }
    // In the full-rate tier, the sample itself.
    const qint64 recent = tiered.lastTime() - 3000;
    QCOMPARE(tiered.valueAt(0, recent)->timeMs, flat.valueAt(0, recent)->timeMs);
    QVERIFY(!tiered.valueAt(0, 129));
}

void TestTelemetryTiers::samplesGivesOnlyTheFullRateTier() {
    TelemetryBuffer buffer(kSeries, tiers(kMinute, 60 * kMinute, kSecond));
    feedSteady(buffer, 0, 10 * kMinute, 100);
    const QList<TelemetryBuffer::Sample> all = buffer.samples(0, 0, 10 * kMinute);
    QCOMPARE(all.size(), buffer.size());
    QCOMPARE(all.first().timeMs, buffer.fullRateFrom());
    QVERIFY(buffer.samples(0, 0, buffer.fullRateFrom()).isEmpty());
    QVERIFY(buffer.firstTime() < buffer.fullRateFrom());
}

void TestTelemetryTiers::olderTierKeepsItsBudgetAndDropsTheOldestSummaries() {
    const TelemetryTiers t = tiers(kMinute, 11 * kMinute, kSecond);
    TelemetryBuffer buffer(kSeries, t);
    QCOMPARE(t.summaryCapacity(), 675); // ten minutes of seconds, with an eighth to spare
    feedSteady(buffer, 0, 5 * kMinute, 100);
    buffer.markGap(5 * kMinute, TelemetryGap::Cause::Disconnected);
    feedSteady(buffer, 6 * kMinute, 60 * kMinute, 100);
    QCOMPARE(buffer.summaryCount(), t.summaryCapacity());
    const qint64 bytes = buffer.memoryBytes();
    feedSteady(buffer, 60 * kMinute, 90 * kMinute, 100);
    QCOMPARE(buffer.memoryBytes(), bytes);
    QCOMPARE(buffer.summaryCount(), t.summaryCapacity());
    QCOMPARE(buffer.firstTime(), buffer.fullRateFrom() - t.summaryCapacity() * kSecond);
    // The budget is what the older tier takes; the full-rate ring adds its slots.
    const qint64 fullRate = buffer.capacity() * qint64(8 + 2 * kSeries.size()) * 5 / 4;
    QVERIFY2(bytes <= t.summaryBudgetBytes(int(kSeries.size())) + fullRate + 4096,
             qPrintable(QStringLiteral("%1 > %2 + %3")
                            .arg(bytes)
                            .arg(t.summaryBudgetBytes(int(kSeries.size())))
                            .arg(fullRate)));
    // A gap of the dropped past is dropped with it.
    QCOMPARE(buffer.gaps().size(), 0);
}

void TestTelemetryTiers::telemetryMakesTieredBuffersUnlessToldACapacity() {
    Telemetry telemetry;
    const TelemetryBuffer &live = telemetry.ensureBuffer(QStringLiteral("01/port1"), kSeries);
    QVERIFY(live.isTiered());
    QCOMPARE(live.tiers(), TelemetryTiers());
    QVERIFY(!telemetry.ensureBuffer(QStringLiteral("01/port2"), kSeries, 500).isTiered());
    TelemetryTiers shorter = tiers(30 * kMinute, 6 * 60 * kMinute, 2 * kSecond);
    telemetry.setTiers(shorter);
    QCOMPARE(telemetry.ensureBuffer(QStringLiteral("01/port3"), kSeries).tiers(), shorter);
    // An existing buffer keeps what it was made with.
    QCOMPARE(telemetry.ensureBuffer(QStringLiteral("01/port1"), kSeries).tiers(), TelemetryTiers());
}

TIPSCOPE_TEST_GUILESS_MAIN(TestTelemetryTiers)

} // namespace tst_telemetrytiers
#include "tst_telemetrytiers.moc"
