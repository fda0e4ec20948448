// Decimation and window statistics are exact: they match a brute-force reading of every sample
// on seeded random data, across the ring's wrap-around and at every summary level, and a lone
// spike in a day of flat data is never lost.
#include "telemetryreference.h"
#include "testmain.h"

#include <QTest>

namespace tst_telemetrydecimation {

using namespace tipscope::model;
using namespace tipscope::model::test;

namespace {

constexpr qint64 kDayStartMs = 1'700'000'000'000;

struct Window {
    qint64 t0 = 0;
    qint64 t1 = 0;
    int buckets = 0;
};

QString describe(const MinMaxBucket &b) {
    return QStringLiteral("{start %1, min %2 at %3, max %4 at %5, count %6}")
        .arg(b.startMs)
        .arg(b.min)
        .arg(b.minTimeMs)
        .arg(b.max)
        .arg(b.maxTimeMs)
        .arg(b.count);
}

bool operator==(const MinMaxBucket &a, const MinMaxBucket &b) {
    return a.startMs == b.startMs && a.minTimeMs == b.minTimeMs && a.min == b.min &&
           a.maxTimeMs == b.maxTimeMs && a.max == b.max && a.count == b.count;
}

bool same(const QList<MinMaxBucket> &a, const QList<MinMaxBucket> &b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const MinMaxBucket &x, const MinMaxBucket &y) { return x == y; });
}

// Windows that start and end anywhere: on samples, between them, inside blocks, before the
// oldest sample held and after the newest; plus the whole history.
QList<Window> randomWindows(SampleGenerator &g, const ReferenceBuffer &reference, int count) {
    const auto &samples = reference.samples();
    const qint64 first = samples.front().timeMs;
    const qint64 last = samples.back().timeMs;
    const auto anchor = [&] {
        const int roll = g.pick(0, 9);
        if (roll == 0)
            return first - g.pick(0, 5000);
        if (roll == 1)
            return last + g.pick(0, 5000);
        const auto &s = samples[size_t(g.pick(0, int(samples.size()) - 1))];
        return s.timeMs + g.pick(-150, 150);
    };
    const int bucketChoices[] = {1, 2, 3, 64, 1000, 1920, 4096};
    QList<Window> windows{{first, last + 1, 1920}, {first - 777, last + 777, 1}};
    for (int i = 0; i < count; ++i) {
        qint64 t0 = anchor();
        qint64 t1 = anchor();
        if (t1 < t0)
            std::swap(t0, t1);
        const int choice = g.pick(0, 7);
        const int buckets = choice < 7 ? bucketChoices[choice] : g.pick(1, 3000);
        windows.append({t0, t1 + 1, buckets});
    }
    return windows;
}

void fill(TelemetryBuffer &buffer, ReferenceBuffer &reference, SampleGenerator &g, int count) {
    for (int i = 0; i < count; ++i) {
        const qint64 time = g.nextTime();
        const QList<qint32> values = g.nextValues();
        QCOMPARE(buffer.append(time, values), AppendResult::Accepted);
        reference.append(time, values);
    }
}

} // namespace

class TestTelemetryDecimation : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void randomHistories_data();
    void decimationKeepsExactMinAndMaxOfEveryBucket_data() { randomHistories_data(); }
    void decimationKeepsExactMinAndMaxOfEveryBucket();
    void blockEdgesKeepExactExtremesOfEveryColumn_data() { randomHistories_data(); }
    void blockEdgesKeepExactExtremesOfEveryColumn();
    void windowStatsMatchBruteForce_data() { randomHistories_data(); }
    void windowStatsMatchBruteForce();
    void oneSampleSpikeInAFlatDaySurvivesDecimation_data();
    void oneSampleSpikeInAFlatDaySurvivesDecimation();
    void gapsInTheDataStayGaps();
    void emptyOrReversedWindowsGiveNothing();
};

void TestTelemetryDecimation::randomHistories_data() {
    QTest::addColumn<int>("capacity");
    QTest::addColumn<int>("count");
    QTest::addColumn<bool>("wide");

    QTest::newRow("ring not yet full") << 10'000 << 7'000 << false;
    QTest::newRow("wrapped once, oldest sample mid-block") << 10'000 << 13'337 << false;
    QTest::newRow("wrapped many times, capacity not a block multiple") << 5'000 << 23'456 << false;
    QTest::newRow("4096-blocks in use, wrapped") << 8'192 << 3 * 8'192 + 100 << false;
    QTest::newRow("262144-blocks in use, wrapped") << 270'000 << 600'001 << false;
    QTest::newRow("values beyond 16 bits") << 10'000 << 15'000 << true;
    QTest::newRow("ring smaller than one block") << 50 << 175 << false;
}

void TestTelemetryDecimation::decimationKeepsExactMinAndMaxOfEveryBucket() {
    QFETCH(int, capacity);
    QFETCH(int, count);
    QFETCH(bool, wide);
    SampleGenerator g(20240611, 2, wide);
    TelemetryBuffer buffer({QStringLiteral("tip"), QStringLiteral("power")}, capacity);
    ReferenceBuffer reference(capacity);
    fill(buffer, reference, g, count);

    for (const Window &w : randomWindows(g, reference, 150)) {
        for (int series = 0; series < 2; ++series) {
            const QList<MinMaxBucket> got = buffer.decimate(series, w.t0, w.t1, w.buckets);
            const QList<MinMaxBucket> want = reference.decimate(series, w.t0, w.t1, w.buckets);
            const QString where = QStringLiteral("series %1, [%2, %3), %4 buckets")
                                      .arg(series)
                                      .arg(w.t0)
                                      .arg(w.t1)
                                      .arg(w.buckets);
            QVERIFY2(got.size() == want.size(), qPrintable(where));
            for (qsizetype i = 0; i < got.size(); ++i) {
                QVERIFY2(got[i] == want[i],
                         qPrintable(where + QStringLiteral(": got ") + describe(got[i]) +
                                    QStringLiteral(", want ") + describe(want[i])));
            }
        }
    }
}

// ColumnEdges::Blocks may move each inner edge by up to half a finest block, so the columns are
// checked against the samples they say they hold: consecutive runs of the window's samples,
// each column's extremes exact (earliest on ties) at their true times, every sample in exactly
// one column, and every edge within half a block of the exact one. Asking for several series at
// once answers what asking for each alone does.
void TestTelemetryDecimation::blockEdgesKeepExactExtremesOfEveryColumn() {
    QFETCH(int, capacity);
    QFETCH(int, count);
    QFETCH(bool, wide);
    SampleGenerator g(99, 2, wide);
    TelemetryBuffer buffer({QStringLiteral("tip"), QStringLiteral("power")}, capacity);
    ReferenceBuffer reference(capacity);
    fill(buffer, reference, g, count);
    const auto &samples = reference.samples();
    const auto firstAtOrAfter = [&samples](qint64 t) {
        return qsizetype(
            std::lower_bound(samples.begin(), samples.end(), t,
                             [](const ReferenceSample &s, qint64 v) { return s.timeMs < v; }) -
            samples.begin());
    };
    int snappedWindows = 0;
    for (Window w : randomWindows(g, reference, 150)) {
        w.buckets = qMin(w.buckets, 64); // long columns, where edges do move
        const QList<QList<MinMaxBucket>> both =
            buffer.decimate(QList<int>{0, 1}, w.t0, w.t1, w.buckets, ColumnEdges::Blocks);
        QCOMPARE(both.size(), 2);
        QCOMPARE(both.at(0).size(), both.at(1).size());
        const QList<MinMaxBucket> exact = reference.decimate(0, w.t0, w.t1, w.buckets);
        const QString where =
            QStringLiteral("[%1, %2), %3 buckets").arg(w.t0).arg(w.t1).arg(w.buckets);
        qsizetype cursor = firstAtOrAfter(w.t0);
        const qsizetype end = firstAtOrAfter(w.t1);
        for (int series = 0; series < 2; ++series) {
            cursor = firstAtOrAfter(w.t0);
            qsizetype exactCursor = cursor;
            qsizetype exactIndex = 0;
            bool moved = false;
            for (const MinMaxBucket &b : both.at(series)) {
                QVERIFY2(b.count > 0 && cursor + b.count <= end, qPrintable(where));
                MinMaxBucket want{b.startMs, 0, 0, 0, 0, b.count};
                for (qsizetype i = cursor; i < cursor + b.count; ++i) {
                    const qint32 v = samples[size_t(i)].values.at(series);
                    const qint64 t = samples[size_t(i)].timeMs;
                    if (i == cursor || v < want.min)
                        want = {want.startMs, t, v, want.maxTimeMs, want.max, b.count};
                    if (i == cursor || v > want.max)
                        want = {want.startMs, want.minTimeMs, want.min, t, v, b.count};
                }
                QVERIFY2(b == want, qPrintable(where + QStringLiteral(": got ") + describe(b) +
                                               QStringLiteral(", want ") + describe(want)));
                cursor += b.count;
                // The exact columns up to this one's start end within half a block of here.
                while (exactIndex < exact.size() && exact.at(exactIndex).startMs <= b.startMs)
                    exactCursor += exact.at(exactIndex++).count;
                QVERIFY2(qAbs(exactCursor - cursor) <= TelemetryBuffer::kFinestBlock / 2,
                         qPrintable(where));
                moved = moved || exactCursor != cursor;
            }
            QVERIFY2(cursor == end, qPrintable(where)); // no sample left out
            if (series == 0 && moved)
                ++snappedWindows;
            QVERIFY(
                same(both.at(series),
                     buffer.decimate(QList<int>{series}, w.t0, w.t1, w.buckets, ColumnEdges::Blocks)
                         .constFirst()));
        }
        QVERIFY(same(buffer.decimate(QList<int>{0, 1}, w.t0, w.t1, w.buckets).at(1),
                     buffer.decimate(1, w.t0, w.t1, w.buckets)));
    }
    // Not a vacuous pass: unless the ring is too small for a column of several blocks, edges
    // did move in some windows.
    if (capacity >= TelemetryBuffer::kSnapMinBlocks * TelemetryBuffer::kFinestBlock * 4)
        QVERIFY(snappedWindows > 0);
}

void TestTelemetryDecimation::windowStatsMatchBruteForce() {
    QFETCH(int, capacity);
    QFETCH(int, count);
    QFETCH(bool, wide);
    SampleGenerator g(7, 2, wide);
    TelemetryBuffer buffer({QStringLiteral("tip"), QStringLiteral("power")}, capacity);
    ReferenceBuffer reference(capacity);
    fill(buffer, reference, g, count);

    for (const Window &w : randomWindows(g, reference, 300)) {
        for (int series = 0; series < 2; ++series) {
            const TelemetryBuffer::Stats got = buffer.windowStats(series, w.t0, w.t1);
            const TelemetryBuffer::Stats want = reference.windowStats(series, w.t0, w.t1);
            QCOMPARE(got.count, want.count);
            QCOMPARE(got.min, want.min);
            QCOMPARE(got.max, want.max);
            // Both divide the same exact integer sum by the same count.
            QCOMPARE(got.mean, want.mean);
        }
    }
}

void TestTelemetryDecimation::oneSampleSpikeInAFlatDaySurvivesDecimation_data() {
    QTest::addColumn<int>("spikeIndex"); // among the samples held, oldest is 0
    QTest::addColumn<qint32>("spikeValue");
    QTest::addColumn<int>("overwritten"); // samples appended beyond the capacity

    QTest::newRow("on the oldest sample") << 0 << 450 << 0;
    QTest::newRow("inside a block") << 100'017 << 450 << 0;
    QTest::newRow("dip on a 4096-block start") << 4'096 * 50 << 20 << 0;
    QTest::newRow("on the newest sample") << 863'999 << 351 << 0;
    QTest::newRow("oldest sample, ring wrapped mid-block") << 0 << 450 << 1'013;
    QTest::newRow("dip after wrap-around") << 500'000 << 349 << 1'013;
}

void TestTelemetryDecimation::oneSampleSpikeInAFlatDaySurvivesDecimation() {
    QFETCH(int, spikeIndex);
    QFETCH(qint32, spikeValue);
    QFETCH(int, overwritten);
    const int capacity = TelemetryBuffer::kDefaultCapacity;
    const qint32 flat = 350;
    TelemetryBuffer buffer({QStringLiteral("tip")}, capacity);
    for (int i = 0; i < capacity + overwritten; ++i) {
        const qint32 value = i == overwritten + spikeIndex ? spikeValue : flat;
        buffer.append(kDayStartMs + qint64(i) * 100, {value});
    }
    const qint64 spikeTime = kDayStartMs + qint64(overwritten + spikeIndex) * 100;

    for (ColumnEdges edges : {ColumnEdges::Exact, ColumnEdges::Blocks}) {
        const QList<MinMaxBucket> buckets =
            buffer.decimate(QList<int>{0}, buffer.firstTime(), buffer.lastTime() + 1, 1920, edges)
                .constFirst();
        QCOMPARE(buckets.size(), 1920);
        int total = 0;
        int spikes = 0;
        for (const MinMaxBucket &b : buckets) {
            total += b.count;
            if (b.min == flat && b.max == flat)
                continue;
            ++spikes;
            const bool up = spikeValue > flat;
            QCOMPARE(up ? b.max : b.min, spikeValue);
            QCOMPARE(up ? b.maxTimeMs : b.minTimeMs, spikeTime);
            QCOMPARE(up ? b.min : b.max, flat);
        }
        QCOMPARE(spikes, 1);
        QCOMPARE(total, capacity);
    }
}

void TestTelemetryDecimation::gapsInTheDataStayGaps() {
    TelemetryBuffer buffer({QStringLiteral("tip")}, 1000);
    for (int i = 0; i < 10; ++i)
        buffer.append(kDayStartMs + i * 100, {300 + i});
    for (int i = 0; i < 10; ++i) // an hour later
        buffer.append(kDayStartMs + 3'600'000 + i * 100, {400 + i});

    // 3601 columns of one second: only the first and the one an hour later hold samples.
    const QList<MinMaxBucket> buckets =
        buffer.decimate(0, kDayStartMs, kDayStartMs + 3'601'000, 3601);
    QCOMPARE(buckets.size(), 2);
    QCOMPARE(buckets[0].startMs, kDayStartMs);
    QCOMPARE(buckets[0].min, 300);
    QCOMPARE(buckets[0].max, 309);
    QCOMPARE(buckets[0].count, 10);
    QCOMPARE(buckets[1].startMs, kDayStartMs + 3'600'000);
    QCOMPARE(buckets[1].minTimeMs, kDayStartMs + 3'600'000);
    QCOMPARE(buckets[1].maxTimeMs, kDayStartMs + 3'600'900);
}

void TestTelemetryDecimation::emptyOrReversedWindowsGiveNothing() {
    TelemetryBuffer buffer({QStringLiteral("tip")}, 100);
    QVERIFY(buffer.decimate(0, 0, 1000, 10).isEmpty());
    QCOMPARE(buffer.windowStats(0, 0, 1000).count, 0);
    buffer.append(500, {1});
    QVERIFY(buffer.decimate(0, 1000, 0, 10).isEmpty());
    QVERIFY(buffer.decimate(0, 500, 500, 10).isEmpty());
    QVERIFY(buffer.decimate(0, 0, 1000, 0).isEmpty());
    QVERIFY(buffer.decimate(1, 0, 1000, 10).isEmpty());
    QVERIFY(buffer.decimate(0, 501, 1000, 10).isEmpty());
    QCOMPARE(buffer.decimate(0, 0, 1000, 10).size(), 1);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestTelemetryDecimation)

} // namespace tst_telemetrydecimation
#include "tst_telemetrydecimation.moc"
