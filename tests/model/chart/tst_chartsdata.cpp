// The charts' non-widget logic on hand-made telemetry: decimation to points (every column's true
// min and max reach the screen), the crosshair readout, the time window's gestures and the event
// markers' store.
#include "model/chart/chartevents.h"
#include "model/chart/chartframe.h"
#include "model/chart/chartviewport.h"
#include "testmain.h"

#include "i18n/translations.h"

#include <QSignalSpy>
#include <QTest>
#include <QTranslator>
#include <random>

namespace tst_chartsdata {

using namespace tipscope;
using namespace tipscope::model;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;
const QStringList kPortSeries = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                 QStringLiteral("power"), QStringLiteral("status")};

// Whether the polyline reaches `value` at `timeMs`: a point there, or a flat stretch at that
// height spanning it (flat runs keep only their ends).
bool reaches(const QList<QPointF> &points, qint64 timeMs, double value) {
    for (qsizetype i = 0; i < points.size(); ++i) {
        if (points.at(i).x() == double(timeMs) && points.at(i).y() == value)
            return true;
        if (i > 0 && points.at(i - 1).y() == value && points.at(i).y() == value &&
            points.at(i - 1).x() <= double(timeMs) && points.at(i).x() >= double(timeMs))
            return true;
    }
    return false;
}
} // namespace

class TestChartsData : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void decimatedPointsKeepEveryColumnsTrueMinAndMax_data();
    void decimatedPointsKeepEveryColumnsTrueMinAndMax();
    void aOneSampleSpikeIsNeverLost();
    void pointsAreInTimeOrderAndLeadInFromTheLeft();
    void readoutIsTheBuffersNewestSampleAtOrBeforeTheInstant();
    void aCurveIsNeverDrawnAcrossAGapAndTheReadoutThereIsBlank_data();
    void aCurveIsNeverDrawnAcrossAGapAndTheReadoutThereIsBlank();
    void hardwareTemperaturesAreTracedOnlyWhenAskedAndTheTransformerOnce();
    void legendNamesAreWholePhrasesInEachLanguage_data();
    void legendNamesAreWholePhrasesInEachLanguage();
    void followingWindowMovesWithTheData();
    void theFirstMinutesFillTheViewUntilTheWindowIsFull();
    void zoomKeepsTheInstantUnderTheCursorAndStopsFollowing();
    void windowLengthStaysBetween30SecondsAnd24Hours();
    void panStopsAtTheData();
    void liveEventsKeepTheNewestWithTheirTextsAndAReplayKeepsAll();
};

void TestChartsData::decimatedPointsKeepEveryColumnsTrueMinAndMax_data() {
    QTest::addColumn<int>("samples");
    QTest::addColumn<int>("columns");
    QTest::addColumn<int>("seed");
    QTest::newRow("fewer samples than columns") << 300 << 1000 << 1;
    QTest::newRow("ten samples a column") << 10'000 << 1000 << 2;
    QTest::newRow("a day at 1920 columns") << 864'000 << 1920 << 3;
    QTest::newRow("odd columns") << 50'000 << 997 << 4;
}

void TestChartsData::decimatedPointsKeepEveryColumnsTrueMinAndMax() {
    QFETCH(int, samples);
    QFETCH(int, columns);
    QFETCH(int, seed);
    TelemetryBuffer buffer(kPortSeries, samples);
    std::mt19937 random{quint32(seed)};
    std::uniform_int_distribution<int> step(-3, 3);
    QList<qint32> tips;
    qint32 tip = 300;
    for (int i = 0; i < samples; ++i) {
        tip += step(random);
        tips.append(tip);
        buffer.append(kT0 + i * 100, {tip, 350, 0, 0});
    }
    const qint64 t1 = kT0 + qint64(samples) * 100;
    const SeriesFormat format =
        seriesFormat(QStringLiteral("tip"), model::TemperatureUnit::Celsius);
    const QList<QPointF> points = minMaxPoints(buffer, 0, kT0, t1, columns, format);
    QVERIFY(points.size() <= 2 * columns);
    // An independent reference: each column's extremes by reading every sample.
    const qint64 span = t1 - kT0;
    int sample = 0;
    for (int k = 0; k < columns; ++k) {
        const qint64 end = kT0 + span * (k + 1) / columns;
        std::optional<int> minAt, maxAt;
        for (; sample < samples && kT0 + sample * 100 < end; ++sample) {
            if (!minAt || tips.at(sample) < tips.at(*minAt))
                minAt = sample;
            if (!maxAt || tips.at(sample) > tips.at(*maxAt))
                maxAt = sample;
        }
        if (!minAt)
            continue;
        QVERIFY2(reaches(points, kT0 + *minAt * 100, tips.at(*minAt)),
                 qPrintable(QStringLiteral("column %1 lost its minimum").arg(k)));
        QVERIFY2(reaches(points, kT0 + *maxAt * 100, tips.at(*maxAt)),
                 qPrintable(QStringLiteral("column %1 lost its maximum").arg(k)));
    }
}

void TestChartsData::aOneSampleSpikeIsNeverLost() {
    TelemetryBuffer buffer(kPortSeries);
    for (int i = 0; i < 864'000; ++i)
        buffer.append(kT0 + i * 100, {i == 431'999 ? 999 : 350, 350, 0, 0});
    const SeriesFormat f = seriesFormat(QStringLiteral("tip"), model::TemperatureUnit::Fahrenheit);
    ValueSpan span;
    const QList<QPointF> points = minMaxPoints(buffer, 0, kT0, kT0 + 86'400'000, 1920, f, &span);
    QCOMPARE(span.max, f.toDisplay(999));
    QVERIFY(reaches(points, kT0 + 431'999LL * 100, f.toDisplay(999)));
    // A flat day needs a handful of points, not two per column.
    QVERIFY2(points.size() < 10, qPrintable(QString::number(points.size())));
}

void TestChartsData::pointsAreInTimeOrderAndLeadInFromTheLeft() {
    TelemetryBuffer buffer(kPortSeries);
    for (int i = 0; i < 5000; ++i)
        buffer.append(kT0 + i * 100, {qint32((i * 37) % 101), 350, 0, 0});
    const SeriesFormat f = seriesFormat(QStringLiteral("tip"), model::TemperatureUnit::Celsius);
    const qint64 t0 = kT0 + 100'050;
    const QList<QPointF> points = minMaxPoints(buffer, 0, t0, kT0 + 400'000, 333, f);
    QVERIFY(!points.isEmpty());
    QCOMPARE(points.first().x(), double(kT0 + 100'000)); // the sample before the window
    for (qsizetype i = 1; i < points.size(); ++i)
        QVERIFY(points.at(i).x() >= points.at(i - 1).x());
}

void TestChartsData::readoutIsTheBuffersNewestSampleAtOrBeforeTheInstant() {
    model::Telemetry telemetry;
    telemetry.ensureBuffer(QStringLiteral("01/port1"), kPortSeries);
    for (int i = 0; i < 100; ++i)
        telemetry.append(QStringLiteral("01/port1"), kT0 + i * 250, {200 + i, 350, i * 10, 0});
    ChartChannel channel;
    channel.key = QStringLiteral("01/port1");
    channel.port = 1;
    channel.series = kPortSeries;
    const QList<ChartTrace> traces = tracesFor({channel}, {0}, model::TemperatureUnit::Celsius);
    QCOMPARE(traces.size(), 3); // tip, setpoint, power; status is no curve
    const QList<ReadoutValue> at = readoutAt(telemetry, {channel}, traces, kT0 + 2600);
    QCOMPARE(at.at(0).sampleMs, kT0 + 2500);
    QCOMPARE(at.at(0).display, 210.0);
    QCOMPARE(at.at(2).display, 10.0); // 100 per mille is 10 %
    QVERIFY(!readoutAt(telemetry, {channel}, traces, kT0 - 1).at(0).valid);
    QVERIFY(readoutText(traces, at, kT0 + 2600).contains(QStringLiteral("P1 tip 210 °C")));
}

void TestChartsData::aCurveIsNeverDrawnAcrossAGapAndTheReadoutThereIsBlank_data() {
    QTest::addColumn<int>("columns");
    QTest::newRow("sparse: a line between samples") << 4000;
    QTest::newRow("dense: a column per pixel") << 200;
}

void TestChartsData::aCurveIsNeverDrawnAcrossAGapAndTheReadoutThereIsBlank() {
    QFETCH(int, columns);
    model::Telemetry telemetry;
    const QString key = QStringLiteral("line|01|DME-2C|1|port1");
    telemetry.ensureBuffer(key, kPortSeries);
    // 60 s at 4 Hz, a 25 s unplug, 60 s more.
    for (int i = 0; i < 240; ++i)
        telemetry.append(key, kT0 + i * 250, {300 + i % 7, 350, 100, 0});
    QVERIFY(telemetry.markGap(key, kT0 + 60'000, TelemetryGap::Cause::LineDown));
    const qint64 back = kT0 + 85'000;
    for (int i = 0; i < 240; ++i)
        telemetry.append(key, back + i * 250, {300 + i % 5, 350, 100, 0});
    ChartChannel channel;
    channel.key = key;
    channel.port = 1;
    channel.series = kPortSeries;
    const QList<ChartTrace> traces = tracesFor({channel}, {0}, model::TemperatureUnit::Celsius);
    const ChartFrame frame =
        buildFrame(telemetry, {channel}, traces, kT0 - 10'000, back + 70'000, columns);
    for (const QList<QPointF> &points : frame.points) {
        int breaks = 0;
        for (qsizetype i = 1; i < points.size(); ++i) {
            const QPointF a = points.at(i - 1);
            const QPointF b = points.at(i);
            if (!std::isfinite(a.y()) || !std::isfinite(b.y())) {
                breaks += std::isfinite(b.y()) ? 0 : 1;
                continue;
            }
            QVERIFY2(!(a.x() < kT0 + 60'000 && b.x() >= back),
                     qPrintable(QStringLiteral("a line joins %1 and %2 across the gap")
                                    .arg(a.x() - kT0)
                                    .arg(b.x() - kT0)));
        }
        QCOMPARE(breaks, 1);
    }
    QVERIFY(!readoutAt(telemetry, {channel}, traces, kT0 + 70'000).at(0).valid);
    QVERIFY(readoutAt(telemetry, {channel}, traces, kT0 + 59'900).at(0).valid);
    QVERIFY(readoutAt(telemetry, {channel}, traces, back).at(0).valid);
}

void TestChartsData::hardwareTemperaturesAreTracedOnlyWhenAskedAndTheTransformerOnce() {
    const QStringList series =
        kPortSeries + QStringList{QStringLiteral("transistor"), QStringLiteral("transformer")};
    QList<ChartChannel> channels(2);
    for (int i = 0; i < 2; ++i) {
        channels[i].port = i + 1;
        channels[i].address = QStringLiteral("01");
        channels[i].series = series;
    }
    const auto names = [&channels](model::TemperatureUnit unit, bool hardware) {
        QStringList out;
        for (const ChartTrace &t : tracesFor(channels, {0, 1}, unit, hardware))
            out.append(t.name + QLatin1Char(' ') + t.format.unit);
        return out;
    };
    QCOMPARE(names(model::TemperatureUnit::Celsius, false).size(), 6);
    const QStringList on = names(model::TemperatureUnit::Fahrenheit, true);
    QCOMPARE(on.size(), 6 + 2 + 1);
    QVERIFY(on.contains(QStringLiteral("P1 transistor °F")));
    QVERIFY(on.contains(QStringLiteral("P2 transistor °F")));
    QCOMPARE(on.count(QStringLiteral("transformer °F")), 1);
}

void TestChartsData::legendNamesAreWholePhrasesInEachLanguage_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<bool>("nounsCapitalised");
    QTest::newRow("German") << "de" << true;
    QTest::newRow("Spanish") << "es" << false;
    QTest::newRow("English") << "en" << false;
}

// German nouns keep their capital in a legend ("P1 Lötspitze", not "P1 lötspitze"), where English
// and Spanish write the same names in lower case ("P1 tip", "P1 punta").
void TestChartsData::legendNamesAreWholePhrasesInEachLanguage() {
    QFETCH(QString, language);
    QFETCH(bool, nounsCapitalised);
    QList<ChartChannel> channels(2);
    channels[0].port = 1;
    channels[0].series =
        kPortSeries + QStringList{QStringLiteral("transistor"), QStringLiteral("transformer")};
    channels[1].series = {QStringLiteral("fed"), QStringLiteral("speed")};
    const QList<ChartTrace> english =
        tracesFor(channels, {0, 1}, model::TemperatureUnit::Celsius, true);
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), language), language);
    const QList<ChartTrace> shown =
        tracesFor(channels, {0, 1}, model::TemperatureUnit::Celsius, true);
    QStringList kinds;
    for (const QString &series : channels[0].series + channels[1].series)
        kinds.append(traceName(series, 0));
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());

    QCOMPARE(shown.size(), english.size());
    QCOMPARE(english.first().name, QStringLiteral("P1 tip"));
    QStringList names = kinds;
    for (const ChartTrace &t : shown)
        names.append(t.name);
    for (const QString &name : names) {
        const QString words =
            name.startsWith(QLatin1String("P1 ")) ? name.mid(3) : name; // after the port
        QVERIFY2(!words.isEmpty(), qPrintable(name));
        if (nounsCapitalised)
            QVERIFY2(words.at(0).isUpper(), qPrintable(name));
        else
            QVERIFY2(words.at(0).isLower(), qPrintable(name));
    }
}

void TestChartsData::followingWindowMovesWithTheData() {
    ChartViewport v;
    QSignalSpy changed(&v, &ChartViewport::changed);
    QVERIFY(changed.isValid());
    v.setDataRange(kT0, kT0 + 600'000);
    QCOMPARE(v.end(), kT0 + 600'001);
    QCOMPARE(v.windowMs(), ChartViewport::kDefaultWindowMs);
    v.setDataRange(kT0, kT0 + 700'000);
    QCOMPARE(v.end(), kT0 + 700'001);
    QCOMPARE(changed.count(), 2);
    v.setFollowing(false);
    v.setDataRange(kT0, kT0 + 800'000);
    QCOMPARE(v.end(), kT0 + 700'001); // paused: the window stays
}

void TestChartsData::theFirstMinutesFillTheViewUntilTheWindowIsFull() {
    ChartViewport v;
    // Ten seconds of data: the shortest window, starting at the first sample (a scope's sweep).
    v.setDataRange(kT0, kT0 + 10'000);
    QCOMPARE(v.start(), kT0);
    QCOMPARE(v.windowMs(), ChartViewport::kMinWindowMs);
    // Two minutes: the window is the data, not a sliver at the right of five empty minutes.
    v.setDataRange(kT0, kT0 + 120'000);
    QCOMPARE(v.start(), kT0);
    QCOMPARE(v.end(), kT0 + 120'001);
    QCOMPARE(v.targetWindowMs(), ChartViewport::kDefaultWindowMs);
    // Full: the chosen length, moving with the data.
    v.setDataRange(kT0, kT0 + 400'000);
    QCOMPARE(v.windowMs(), ChartViewport::kDefaultWindowMs);
    QCOMPARE(v.end(), kT0 + 400'001);
    // Paused while filling, the window keeps its span; zoomed, the target is the zoomed span.
    v.setDataRange(kT0 + 1000, kT0 + 61'000);
    v.zoom(0.5, v.end());
    QVERIFY(!v.isFollowing());
    QCOMPARE(v.targetWindowMs(), v.windowMs());
    QCOMPARE(v.windowMs(), (60'001 + 1) / 2);
}

void TestChartsData::zoomKeepsTheInstantUnderTheCursorAndStopsFollowing() {
    ChartViewport v;
    v.setDataRange(kT0, kT0 + 3600'000);
    const qint64 anchor = v.start() + v.windowMs() / 4;
    const double fraction = double(anchor - v.start()) / double(v.windowMs());
    v.zoom(0.5, anchor);
    QVERIFY(!v.isFollowing());
    QCOMPARE(v.windowMs(), ChartViewport::kDefaultWindowMs / 2);
    QVERIFY(qAbs(double(anchor - v.start()) / double(v.windowMs()) - fraction) < 1e-3);
    v.reset();
    QVERIFY(v.isFollowing());
    QCOMPARE(v.windowMs(), ChartViewport::kDefaultWindowMs);
}

void TestChartsData::windowLengthStaysBetween30SecondsAnd24Hours() {
    ChartViewport v;
    v.setDataRange(kT0, kT0 + 48 * 3600'000LL);
    v.zoom(1e-6, v.end());
    QCOMPARE(v.windowMs(), ChartViewport::kMinWindowMs);
    v.zoom(1e6, v.end());
    QCOMPARE(v.windowMs(), ChartViewport::kMaxWindowMs);
    v.showRange(kT0 + 1000, kT0 + 2000); // grows around its middle
    QCOMPARE(v.windowMs(), ChartViewport::kMinWindowMs);
    QCOMPARE(v.start() + v.windowMs() / 2, kT0 + 1500);
}

void TestChartsData::panStopsAtTheData() {
    ChartViewport v;
    v.setDataRange(kT0, kT0 + 3600'000);
    v.pan(-100 * 3600'000LL);
    QVERIFY(!v.isFollowing());
    QVERIFY(v.end() > kT0); // some of the data stays in view
    v.pan(1000 * 3600'000LL);
    QVERIFY(v.start() < kT0 + 3600'000);
}

void TestChartsData::liveEventsKeepTheNewestWithTheirTextsAndAReplayKeepsAll() {
    ChartEvents live;
    ChartEvents replay(ChartEvents::kUnbounded);
    constexpr int kCount = 3 * ChartEvents::kLiveCapacity;
    for (int i = 0; i < kCount; ++i) {
        // Now and then one arrives late, stamped before the one added just before it.
        const qint64 t = kT0 + i * 100 - (i % 7 == 0 ? 150 : 0);
        const ChartEvent e{t,
                           model::Event::Kind::Write,
                           model::Event::Severity::Info,
                           QStringLiteral("@01"),
                           QStringLiteral("ST1 = %1 °C").arg(i),
                           QString()};
        live.add(e);
        replay.add(e);
    }
    QCOMPARE(live.size(), ChartEvents::kLiveCapacity);
    QCOMPARE(replay.size(), qsizetype(kCount));
    const QList<ChartEvent> kept = live.between(kT0, kT0 + kCount * 100LL);
    QCOMPARE(kept.size(), ChartEvents::kLiveCapacity);
    for (qsizetype i = 1; i < kept.size(); ++i)
        QVERIFY(kept.at(i - 1).timeMs <= kept.at(i).timeMs);
    QCOMPARE(kept.last().text, QStringLiteral("ST1 = %1 °C").arg(kCount - 1));
    QCOMPARE(kept.last().scope, QStringLiteral("@01"));
    const QList<ChartEvent> all = replay.between(kT0 - 1000, kT0 + kCount * 100LL);
    QCOMPARE(all.size(), qsizetype(kCount));
    QCOMPARE(all.first().text, QStringLiteral("ST1 = 0 °C"));
    // Held as UTF-8 with a small entry each: about what the texts take in a CSV.
    QVERIFY2(replay.memoryBytes() < kCount * 60, qPrintable(QString::number(replay.memoryBytes())));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestChartsData)

} // namespace tst_chartsdata
#include "tst_chartsdata.moc"
