// The chart's own drawing of curves, read back from the pixels of the real widget: a one-sample
// spike in a day of data reaches the screen, temperatures stay on top of a dense power curve, a
// gap in the data stays a gap, and a sparse curve is drawn as a line between its points.
#include "charts/chartwidget.h"
#include "model/chart/chartframe.h"
#include "testmain.h"

#include <QGraphicsTextItem>
#include <QGraphicsView>
#include <QScreen>
#include <QTest>
#include <cmath>
#include <tuple>

namespace tst_chartwidget {

using namespace tipscope;
using namespace tipscope::gui;
using namespace tipscope::model;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;
constexpr qint64 kDayMs = 86'400'000;
const QColor kTip(0x00, 0x72, 0xB2);
const QColor kPower(0xD5, 0x5E, 0x00);

// Whether a pixel of `color` lies within `slack` pixels of `at` in the chart's image.
bool colorNear(const QImage &image, QPointF at, const QColor &color, int slack = 1) {
    for (int dx = -slack; dx <= slack; ++dx)
        for (int dy = -slack; dy <= slack; ++dy) {
            const QPoint p(int(at.x()) + dx, int(at.y()) + dy);
            if (image.valid(p) && image.pixelColor(p).rgb() == color.rgb())
                return true;
        }
    return false;
}

// Pixels of `color` in the pixel column `x`, between the plot's top and bottom.
int colorInColumn(const QImage &image, int x, const QRectF &plot, const QColor &color) {
    int n = 0;
    for (int y = int(plot.top()); y < int(plot.bottom()); ++y)
        n += image.pixelColor(x, y).rgb() == color.rgb() ? 1 : 0;
    return n;
}
} // namespace

class TestChartWidget : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup() { delete m_chart; }
    void aOneSampleSpikeInADayReachesTheScreen();
    void temperaturesAreDrawnOverADensePowerCurve();
    void aGapInDenseDataStaysEmpty();
    void aSparseCurveIsALineThroughItsPoints();
    void aFollowingChartRepaintsOnlyPartsAndLeavesNothingStale();
    void aShortPaneLabelsFewerValuesSoTheyDoNotCrowd();
    void aPanePerPortLabelsEveryValueItShowsInFull();
    void theValuesAreWrittenAsTheWindowsLanguageWritesThem();
    void anAlarmLabelNeverCoversACurve();

private:
    void show(qint64 t0, qint64 t1, const QList<QList<QPointF>> &points);

    ChartWidget *m_chart = nullptr;
};

void TestChartWidget::init() {
    m_chart = new ChartWidget;
    m_chart->setSeries({{QStringLiteral("tip"), kTip, Qt::SolidLine, ChartAxis::Left},
                        {QStringLiteral("power"), kPower, Qt::DotLine, ChartAxis::Right}});
    m_chart->resize(1200, 600);
    m_chart->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_chart));
}

void TestChartWidget::show(qint64 t0, qint64 t1, const QList<QList<QPointF>> &points) {
    m_chart->showData(ChartData{t0, t1, 0, 1000, 0, 100, points});
    QCoreApplication::processEvents();
}

void TestChartWidget::aOneSampleSpikeInADayReachesTheScreen() {
    TelemetryBuffer buffer({QStringLiteral("tip")});
    const int spikeAt = 612'345;
    for (int i = 0; i < 864'000; ++i)
        buffer.append(kT0 + i * 100, {i == spikeAt ? 900 : 340 + (i * 7919) % 21});
    const SeriesFormat f = seriesFormat(QStringLiteral("tip"), model::TemperatureUnit::Celsius);
    show(kT0, kT0 + kDayMs, {});
    const QList<QPointF> points =
        minMaxPoints(buffer, 0, kT0, kT0 + kDayMs, m_chart->plotWidth(), f);
    QVERIFY(points.size() > m_chart->plotWidth()); // dense: drawn as columns
    show(kT0, kT0 + kDayMs, {points, {}});
    const QImage image = m_chart->toImage();
    const QPointF spike = m_chart->seriesPosition(0, QPointF(double(kT0 + spikeAt * 100LL), 900));
    QVERIFY2(colorNear(image, spike, kTip),
             qPrintable(QStringLiteral("no tip pixel at %1,%2").arg(spike.x()).arg(spike.y())));
    // Nowhere else does the curve reach that high.
    const QPointF elsewhere = m_chart->seriesPosition(0, QPointF(double(kT0 + 3'600'000), 900));
    QVERIFY(!colorNear(image, elsewhere, kTip, 3));
}

void TestChartWidget::temperaturesAreDrawnOverADensePowerCurve() {
    // Power bursts from 0 to 100 % in every column; the tip sits at 500 across the day.
    QList<QPointF> tip;
    QList<QPointF> power;
    const int columns = m_chart->plotWidth();
    for (int k = 0; k < columns * 2; ++k) {
        const double t = double(kT0) + double(kDayMs) * k / (columns * 2);
        tip.append(QPointF(t, 500 + (k % 2)));
        power.append(QPointF(t, k % 2 ? 100 : 0));
    }
    show(kT0, kT0 + kDayMs, {tip, power});
    const QImage image = m_chart->toImage();
    const QRectF plot = m_chart->plotArea();
    int tipOnTop = 0;
    int checked = 0;
    for (int x = int(plot.left()) + 2; x < int(plot.right()) - 2; x += 97, ++checked) {
        const QPointF at = m_chart->seriesPosition(0, QPointF(m_chart->timeAt(x + 0.5), 500));
        tipOnTop += image.pixelColor(x, int(at.y())).rgb() == kTip.rgb() ? 1 : 0;
        // The power column fills the rest, in the paler colour of a dotted curve.
        QVERIFY(colorInColumn(image, x, plot, kPower) == 0);
    }
    QCOMPARE(tipOnTop, checked);
}

void TestChartWidget::aGapInDenseDataStaysEmpty() {
    QList<QPointF> tip;
    const int columns = m_chart->plotWidth();
    for (int k = 0; k < columns * 2; ++k) {
        if (k > columns / 2 && k < columns) // a quarter of the day without samples
            continue;
        tip.append(QPointF(double(kT0) + double(kDayMs) * k / (columns * 2), 300 + (k % 7)));
    }
    show(kT0, kT0 + kDayMs, {tip, {}});
    const QImage image = m_chart->toImage();
    const QRectF plot = m_chart->plotArea();
    const int inGap = int(m_chart->xAt(kT0 + kDayMs * 3 / 8));
    const int before = int(m_chart->xAt(kT0 + kDayMs / 8));
    QCOMPARE(colorInColumn(image, inGap, plot, kTip), 0);
    QVERIFY(colorInColumn(image, before, plot, kTip) > 0);
}

void TestChartWidget::aSparseCurveIsALineThroughItsPoints() {
    const qint64 t1 = kT0 + 60'000;
    show(kT0, t1, {{QPointF(double(kT0), 200), QPointF(double(t1), 600)}, {}});
    const QImage image = m_chart->toImage();
    // Half way along, the line is half way up.
    const QPointF middle = m_chart->seriesPosition(0, QPointF(double(kT0 + 30'000), 400));
    QVERIFY(colorNear(image, middle, kTip));
    QCOMPARE(m_chart->pointCount(0), 2);
}

// A frame repaints the plot and the time labels' old and new places only. What the window shows
// (the offscreen platform's backing store) must then still equal a full repaint: no label or
// grid line left behind where it was a frame ago.
void TestChartWidget::aFollowingChartRepaintsOnlyPartsAndLeavesNothingStale() {
    QList<QPointF> tip;
    for (int i = 0; i <= 600; ++i)
        tip.append(QPointF(double(kT0 + i * 1000), 300 + 200 * std::sin(i / 20.0)));
    show(kT0, kT0 + 300'000, {tip, {}});
    QTest::qWait(50);
    for (qint64 step = 1; step <= 12; ++step) { // a following window, 7.3 s a step
        show(kT0 + step * 7300, kT0 + 300'000 + step * 7300, {tip, {}});
    }
    QTest::qWait(50);
    const QImage onScreen = m_chart->screen()
                                ->grabWindow(m_chart->winId())
                                .toImage()
                                .convertToFormat(QImage::Format_RGB32);
    const QImage repainted = m_chart->grab().toImage().convertToFormat(QImage::Format_RGB32);
    QCOMPARE(onScreen.size(), repainted.size());
    int differing = 0;
    for (int y = 0; y < onScreen.height(); ++y)
        for (int x = 0; x < onScreen.width(); ++x)
            differing += onScreen.pixel(x, y) != repainted.pixel(x, y) ? 1 : 0;
    QCOMPARE(differing, 0);
}

// German writes 10,2 where English writes 10.2: the value axes as the rest of the window.
void TestChartWidget::theValuesAreWrittenAsTheWindowsLanguageWritesThem() {
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    auto *german = new ChartWidget;
    german->setSeries({{QStringLiteral("speed"), kPower, Qt::DotLine, ChartAxis::Left}});
    german->resize(1200, 600);
    german->show();
    QVERIFY(QTest::qWaitForWindowExposed(german));
    german->showData(ChartData{kT0, kT0 + 60'000, 9.5, 10.5, 0, 1, {}});
    QCoreApplication::processEvents();
    QStringList texts;
    for (QGraphicsView *view : german->findChildren<QGraphicsView *>())
        for (QGraphicsItem *item : view->scene()->items())
            if (auto *text = dynamic_cast<QGraphicsTextItem *>(item); text && text->isVisible())
                texts.append(text->toPlainText());
    delete german;
    QLocale::setDefault(before);
    QVERIFY2(texts.contains(QStringLiteral("10,2")) && !texts.contains(QStringLiteral("10.2")),
             qPrintable(texts.join(QStringLiteral(" | "))));
}

void TestChartWidget::aShortPaneLabelsFewerValuesSoTheyDoNotCrowd() {
    // The feeder's pane is about this short; 0-25 mm in steps of 5 crowded six labels into it.
    const double labelHeight = QFontMetricsF(m_chart->valueLabelFont()).height();
    m_chart->showData(ChartData{kT0, kT0 + 60'000, 0, 25, 9.5, 10.5, {}});
    QCoreApplication::processEvents();
    QCOMPARE(m_chart->valueTickStep(ChartAxis::Left), 5.0); // a tall pane: five steps
    QCOMPARE(m_chart->valueTickStep(ChartAxis::Right), 0.2);
    m_chart->resize(1200, 150);
    QTRY_VERIFY(m_chart->plotArea().height() < 80);
    const double height = m_chart->plotArea().height();
    // The labelled values: multiples of the step within the range, a label height apart at least.
    const auto labels = [&](ChartAxis axis, double min, double max) {
        const double step = m_chart->valueTickStep(axis);
        const double count = std::floor(max / step + 1e-9) - std::ceil(min / step - 1e-9) + 1;
        const double spacing = step / (max - min) * height;
        return std::make_pair(count, spacing);
    };
    const auto [left, leftSpacing] = labels(ChartAxis::Left, 0, 25);
    QVERIFY2(left >= 2 && leftSpacing >= 2 * labelHeight,
             qPrintable(QStringLiteral("%1 labels %2 px apart").arg(left).arg(leftSpacing)));
    const auto [right, rightSpacing] = labels(ChartAxis::Right, 9.5, 10.5);
    QVERIFY2(right >= 1 && (right == 1 || rightSpacing >= 2 * labelHeight),
             qPrintable(QStringLiteral("%1 labels %2 px apart").arg(right).arg(rightSpacing)));
    // Tall again, the steps come back.
    m_chart->resize(1200, 600);
    QTRY_COMPARE(m_chart->valueTickStep(ChartAxis::Left), 5.0);
}

// Issue 39: a pane per port is 170 px tall; at least four labels asked for steps of 20 on
// 240-360 °C and 0-100 %, seven labels too close together, each of which Qt Charts showed as "…".
void TestChartWidget::aPanePerPortLabelsEveryValueItShowsInFull() {
    const double labelHeight = QFontMetricsF(m_chart->valueLabelFont()).height();
    m_chart->setCompact(true); // as the page makes it: the legend beside the plot
    m_chart->resize(900, 170);
    m_chart->showData(ChartData{kT0, kT0 + 60'000, 240, 360, 0, 100, {}});
    QTRY_VERIFY(m_chart->plotArea().height() < 120);
    QCoreApplication::processEvents();
    const double height = m_chart->plotArea().height();
    for (const auto &[axis, min, max] :
         {std::tuple{ChartAxis::Left, 240.0, 360.0}, std::tuple{ChartAxis::Right, 0.0, 100.0}}) {
        const double step = m_chart->valueTickStep(axis);
        const double count = std::floor(max / step + 1e-9) - std::ceil(min / step - 1e-9) + 1;
        const double spacing = step / (max - min) * height;
        const QString what = QStringLiteral("%1 labels %2 px apart in a %3 px plot, %4 px each")
                                 .arg(count)
                                 .arg(spacing)
                                 .arg(height)
                                 .arg(labelHeight);
        QVERIFY2(count >= 3 && spacing >= 1.3 * labelHeight, qPrintable(what));
    }
}

void TestChartWidget::anAlarmLabelNeverCoversACurve() {
    const qint64 t1 = kT0 + 60'000;
    const ChartBand high{
        ChartAxis::Left, 500, qInf(), Qt::red, QStringLiteral("High alarm 500 °C"), true};
    m_chart->setBands({high});
    // A curve just inside the band at the left: the label moves along the line.
    show(kT0, t1,
         {{QPointF(double(kT0), 510), QPointF(double(kT0 + 20'000), 510),
           QPointF(double(kT0 + 20'001), 300), QPointF(double(t1), 300)},
          {}});
    QVERIFY(!m_chart->toImage().isNull()); // paints
    QList<QRectF> labels = m_chart->bandLabelRects();
    QCOMPARE(labels.size(), 1);
    const double curveEnd = m_chart->xAt(kT0 + 20'000);
    QVERIFY2(
        labels.first().left() > curveEnd,
        qPrintable(
            QStringLiteral("label at %1, curve to %2").arg(labels.first().left()).arg(curveEnd)));
    // A curve along the whole line, on both sides of it: no place is free, so no label.
    QList<QPointF> zigzag;
    for (int i = 0; i <= 600; ++i)
        zigzag.append(QPointF(double(kT0 + i * 100), i % 2 ? 530 : 470));
    show(kT0, t1, {zigzag, {}});
    QVERIFY(!m_chart->toImage().isNull());
    QCOMPARE(m_chart->bandLabelRects().size(), 0);
}

TIPSCOPE_TEST_MAIN(TestChartWidget)

} // namespace tst_chartwidget
#include "tst_chartwidget.moc"
