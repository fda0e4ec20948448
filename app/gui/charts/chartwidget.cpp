#include "chartwidget.h"

#include "chartwidget_p.h"

#include <QDateTime>
#include <QLocale>
#include <QPainter>
#include <QVBoxLayout>
#include <cmath>

namespace tipscope::gui {

using model::ChartAxis;

namespace {
constexpr double kMarkerHitPx = 5;

constexpr int kMaxValueSteps = 5;
constexpr int kMinValueLabels = 4;
constexpr double kLabelRoom = 1.3; // label heights from one value label to the next, at least

// 1, 2 or 5 times a power of ten, at least `span / steps`: ticks on round values. A step wider
// than the span would label one value at most, so the next smaller round step is taken then.
double valueStep(double span, int steps) {
    if (!(span > 0))
        return 1;
    const double raw = span / qMax(1, steps);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    constexpr double kRound[] = {0.5, 1, 2, 5, 10};
    int k = 1;
    while (k < 4 && magnitude * kRound[k] < raw)
        ++k;
    return magnitude * kRound[magnitude * kRound[k] > span ? k - 1 : k];
}

// The next round step below `step` (5 → 2.5 → 2 → 1 → 0.5 times a power of ten).
double smallerStep(double step) {
    const double magnitude = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    const double lead = step / magnitude;
    return magnitude * (lead > 4.5 ? 2.5 : lead > 2.25 ? 2 : lead > 1.5 ? 1 : 0.5);
}

// How many multiples of `step` lie in [min, max]: the labels the axis will show.
int labelsWithin(double min, double max, double step) {
    return int(std::floor(max / step + 1e-9) - std::ceil(min / step - 1e-9)) + 1;
}

void styleValueAxis(QValueAxis *axis) {
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0);
    // With a precision: Qt Charts localizes only a format that gives one ("%g" came out empty).
    axis->setLabelFormat(QStringLiteral("%.6g"));
    axis->setMinorTickCount(0);
}
} // namespace

// One pixel wide: the raster engine draws such pens with its cosmetic line stroker. A wider pen
// is stroked into a polygon and filled, which for a min/max zigzag of thousands of segments
// took over a minute a frame (tipscope-bench chart).
QPen tracePen(const ChartSeriesStyle &style) {
    QPen pen(style.color, 1, style.style);
    pen.setCosmetic(true);
    return pen;
}

ChartWidgetPrivate::ChartWidgetPrivate(ChartWidget &owner) {
    chart = new QChart;
    chart->setAnimationOptions(QChart::NoAnimation); // animations re-run on every replace()
    // The light theme's background is a white-to-white gradient: a plain white fill looks the
    // same and is the cheapest thing to repaint under the curves on every frame.
    chart->setBackgroundBrush(QColor(Qt::white));
    // The value axes' numbers as the rest of the window writes them (QLocale(): "10,5" in
    // German); Qt Charts writes them in C's "10.5" otherwise.
    chart->setLocalizeNumbers(true);
    chart->setLocale(QLocale());
    applyMargins();
    chart->legend()->setAlignment(Qt::AlignTop);
    // The time axis only holds the plot's bottom edge: its range never changes, and the ticks,
    // grid lines and labels of time are drawn by ChartPlotView. Moving a Qt Charts axis relaid
    // its rich-text labels on every frame of a following chart, the dearest part of a redraw.
    timeAxis = new QValueAxis(chart);
    timeAxis->setRange(0, 1);
    timeAxis->setTickCount(2);
    timeAxis->setLabelsVisible(false);
    timeAxis->setGridLineVisible(false);
    leftAxis = new QValueAxis(chart);
    rightAxis = new QValueAxis(chart);
    styleValueAxis(leftAxis);
    styleValueAxis(rightAxis);
    // ChartPlotView draws the value grid too: Qt Charts paints it as one item per line, and
    // walking and painting those items was more than drawing the lines in one call.
    leftAxis->setGridLineVisible(false);
    rightAxis->setGridLineVisible(false);
    chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries); // dashes tell series apart
    chart->addAxis(timeAxis, Qt::AlignBottom);
    chart->addAxis(leftAxis, Qt::AlignLeft);
    chart->addAxis(rightAxis, Qt::AlignRight);
    rightAxis->setVisible(false);
    view = new ChartPlotView(chart, owner);
    crosshair = new QGraphicsLineItem(chart);
    crosshair->setPen(QPen(QColor(60, 60, 60, 180), 1));
    crosshair->setZValue(100);
    crosshair->setVisible(false);
    emptyText = new QGraphicsSimpleTextItem(chart);
    emptyText->setBrush(QColor(120, 120, 120));
    emptyText->setZValue(100);
    emptyText->setVisible(false);
}

void ChartWidgetPrivate::applyMargins() {
    chart->setMargins(QMargins(4 + padLeft, 4, 4 + padRight, 4 + timeLabelStrip()));
    if (view) // none yet while the chart is being made
        view->fitChart();
}

// Only the plot: Qt Charts repaints the axis labels and the legend itself when they change, and
// repainting their rich-text items on every frame was most of a live chart's painting.
void ChartWidgetPrivate::updatePlot() {
    const QRectF plotArea = plot();
    const QRect p = plotArea.toAlignedRect();
    // And the tick marks under it, and the time labels where they were and where they go.
    QRegion labels;
    for (const TimeLabel &l : timeLabels(plotArea))
        labels += l.rect.toAlignedRect().adjusted(-1, -1, 1, 1);
    const QRect marks(p.left() - 1, p.bottom(), p.width() + 2, 7);
    view->viewport()->update(QRegion(p.adjusted(-1, -1, 1, 1)) + marks + labels + timeLabelsRegion);
    timeLabelsRegion = labels;
}

QList<ChartWidgetPrivate::TimeLabel> ChartWidgetPrivate::timeLabels(const QRectF &plot) const {
    const QFont font = leftAxis->labelsFont();
    if (tickTexts.size() != tickLabels.size() || tickTextFont != font) {
        tickTexts.clear();
        tickTextFont = font;
        for (const QString &label : tickLabels) {
            QStaticText text(label);
            text.setTextFormat(Qt::PlainText);
            text.prepare(QTransform(), font);
            tickTexts.append(text);
        }
    }
    QList<TimeLabel> out;
    if (t1 <= t0)
        return out;
    const QRectF scene = view->sceneRect();
    for (qsizetype i = 0; i < ticks.size() && i < tickTexts.size(); ++i) {
        const double x =
            std::round(plot.left() + double(ticks.at(i) - t0) / double(t1 - t0) * plot.width());
        if (x < plot.left() || x > plot.right())
            continue;
        const QSizeF size = tickTexts.at(i).size();
        // Centred on the tick, but inside the scene; a scene narrower than the label (a widget
        // not laid out yet) keeps its left edge.
        const double left =
            qMax(scene.left(), qMin(x - size.width() / 2, scene.right() - size.width()));
        out.append({x, QRectF(QPointF(left, plot.bottom() + 6), size), i});
    }
    return out;
}

double ChartWidgetPrivate::yAt(ChartAxis axis, double value, const QRectF &plot) const {
    const double *r = ranges[axis == ChartAxis::Left ? 0 : 1];
    const double span = r[1] - r[0];
    return span > 0 ? plot.bottom() - (value - r[0]) / span * plot.height() : plot.bottom();
}

void ChartWidgetPrivate::placeOverlays() {
    const QRectF p = plot();
    if (crosshairTime && *crosshairTime >= t0 && *crosshairTime < t1) {
        const double x = p.left() + double(*crosshairTime - t0) / double(t1 - t0) * p.width();
        crosshair->setLine(x, p.top(), x, p.bottom());
        crosshair->setVisible(true);
    } else {
        crosshair->setVisible(false);
    }
    const QRectF text = emptyText->boundingRect();
    emptyText->setPos(p.center() - QPointF(text.width() / 2, text.height() / 2));
}

int ChartWidgetPrivate::timeLabelStrip() const {
    return QFontMetrics(leftAxis ? leftAxis->labelsFont() : QFont()).height() + 8;
}

void ChartWidgetPrivate::updateTimeTicks() {
    static constexpr qint64 kSteps[] = {1000,       2000,      5000,      10'000,    15'000,
                                        30'000,     60'000,    120'000,   300'000,   600'000,
                                        900'000,    1'800'000, 3'600'000, 7'200'000, 10'800'000,
                                        21'600'000, 43'200'000};
    const int maxTicks = qMax(2, int(plot().width() / 90));
    qint64 step = kSteps[std::size(kSteps) - 1];
    for (qint64 candidate : kSteps) {
        if ((t1 - t0) / candidate <= maxTicks) {
            step = candidate;
            break;
        }
    }
    // Rounded on the local clock, so hours and minutes are the ones people read on the wall.
    if (const qint64 quarter = t0 / 900'000; quarter != utcOffsetQuarter) {
        utcOffsetQuarter = quarter;
        utcOffsetMs = qint64(QDateTime::fromMSecsSinceEpoch(t0).offsetFromUtc()) * 1000;
    }
    const qint64 offset = utcOffsetMs;
    QList<qint64> wanted;
    for (qint64 t = ((t0 + offset + step - 1) / step) * step - offset; t < t1; t += step)
        wanted.append(t);
    if (wanted == ticks && step == tickStep)
        return;
    ticks = wanted;
    tickStep = step;
    tickLabels.clear();
    tickTexts.clear();
    const QString format = step < 60'000 ? QStringLiteral("HH:mm:ss") : QStringLiteral("HH:mm");
    for (qint64 t : std::as_const(wanted)) {
        const QDateTime time = QDateTime::fromMSecsSinceEpoch(t);
        const bool midnight = time.time().hour() == 0 && time.time().minute() == 0;
        tickLabels.append(
            time.toString(midnight && step >= 3600'000 ? QStringLiteral("dd.MM.") : format));
    }
}

void ChartWidgetPrivate::updateValueTicks() {
    // A label's height and as much again between labels; until laid out, the most steps.
    const double labelHeight = QFontMetricsF(leftAxis->labelsFont()).height();
    const double height = plot().height();
    const int steps =
        height > 0 ? qBound(1, int(height / (2 * labelHeight)), kMaxValueSteps) : kMaxValueSteps;
    // At least four labelled values where the pane has room for them: two labels say little
    // about the scale of a curve between them.
    const int wanted = steps + 1 >= kMinValueLabels ? kMinValueLabels : 1;
    // Never more labels than fit a little apart: Qt Charts shows a label taller than the room
    // between it and the next as "…" (a pane per port is short).
    const int fit = height > 0 ? int(height / (kLabelRoom * labelHeight)) + 1 : kMaxValueSteps + 1;
    for (int i = 0; i < 2; ++i) {
        const double span = ranges[i][1] - ranges[i][0];
        if (!(span > 0))
            continue;
        QValueAxis *axis = i == 0 ? leftAxis : rightAxis;
        double step = valueStep(span, steps);
        while (labelsWithin(ranges[i][0], ranges[i][1], step) < wanted && step > span * 1e-6 &&
               labelsWithin(ranges[i][0], ranges[i][1], smallerStep(step)) <= fit)
            step = smallerStep(step);
        if (axis->tickInterval() != step)
            axis->setTickInterval(step);
    }
}

ChartWidget::ChartWidget(QWidget *parent)
    : QWidget(parent)
    , d(std::make_unique<ChartWidgetPrivate>(*this)) {
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(d->view);
    setFocusProxy(d->view);
    connect(d->chart, &QChart::plotAreaChanged, this, [this] {
        d->laidOutPadLeft = d->padLeft;
        d->laidOutPadRight = d->padRight;
        // The plot moved: a redraw's partial updates would leave the time labels drawn where it
        // was, so the whole chart is painted again (this happens on a layout, not on a redraw).
        d->view->viewport()->update();
        d->updateValueTicks();
        d->placeOverlays();
        d->updateTimeTicks();
        Q_EMIT plotResized();
    });
}

ChartWidget::~ChartWidget() = default;

void ChartWidget::setTitle(const QString &title) {
    d->title = title;
    d->showTitle();
    d->view->setAccessibleName(title);
}

void ChartWidget::setTitleShown(bool shown) {
    d->titleShown = shown;
    d->showTitle();
}

void ChartWidget::setCompact(bool compact) {
    d->compact = compact;
    d->showTitle();
    d->placeLegend();
}

void ChartWidgetPrivate::showTitle() {
    chart->setTitle(compact || !titleShown ? QString() : title);
}

QPair<int, int> ChartWidget::naturalPlotInsets() const {
    const QRectF p = d->plot();
    const double width = d->chart->size().width();
    return {int(std::lround(p.left())) - d->laidOutPadLeft,
            int(std::lround(width - p.right())) - d->laidOutPadRight};
}

bool ChartWidget::hasRoom() const {
    return d->plot().width() >= kMinAlignedPlotPx;
}

void ChartWidget::alignPlot(int left, int right) {
    const auto [naturalLeft, naturalRight] = naturalPlotInsets();
    int padLeft = qMax(0, left - naturalLeft);
    int padRight = qMax(0, right - naturalRight);
    // Padding past the chart's own width would squeeze its plot below any use: the chart keeps
    // its natural room until it has enough to line up with the others.
    const double spare = d->chart->size().width() - naturalLeft - naturalRight - kMinAlignedPlotPx;
    if (padLeft + padRight > spare)
        padLeft = padRight = 0;
    if (padLeft == d->padLeft && padRight == d->padRight)
        return;
    d->padLeft = padLeft;
    d->padRight = padRight;
    d->applyMargins();
}

void alignPlots(const QList<ChartWidget *> &charts) {
    int left = 0;
    int right = 0;
    for (const ChartWidget *c : charts) {
        if (!c->hasRoom())
            continue;
        const auto [l, r] = c->naturalPlotInsets();
        left = qMax(left, l);
        right = qMax(right, r);
    }
    for (ChartWidget *c : charts)
        c->alignPlot(left, right);
}

// Above the plot the legend is one row, and Qt Charts cuts its names short ("P1 …") when they do
// not fit: a short pane, or more entries than four ports' tip, setpoint and power, list them on
// the right, one a line.
void ChartWidgetPrivate::placeLegend() {
    constexpr qsizetype kOneRow = 12;
    chart->legend()->setAlignment(compact || series.size() > kOneRow ? Qt::AlignRight
                                                                     : Qt::AlignTop);
}

void ChartWidget::setSeries(const QList<ChartSeriesStyle> &styles,
                            const QList<ChartSeriesStyle> &legend) {
    for (QLineSeries *s : std::as_const(d->series)) {
        d->chart->removeSeries(s);
        delete s;
    }
    d->series.clear();
    d->styles = styles;
    d->points = QList<QList<QPointF>>(styles.size());
    bool anyRight = false;
    for (const ChartSeriesStyle &style : styles)
        anyRight = anyRight || style.axis == ChartAxis::Right;
    for (const ChartSeriesStyle &style : legend.isEmpty() ? styles : legend) {
        // The series stays empty: it gives the legend its entry and nothing else. The curve is
        // drawn by ChartPlotView (see drawTraces()).
        auto *s = new QLineSeries;
        s->setName(style.name);
        s->setPen(tracePen(style));
        d->chart->addSeries(s);
        // Empty, it paints nothing, yet the scene would visit its item on every frame; a fully
        // transparent item it skips. The legend entry keeps its own opacity.
        s->setOpacity(0);
        s->attachAxis(d->timeAxis);
        s->attachAxis(style.axis == ChartAxis::Left ? d->leftAxis : d->rightAxis);
        d->series.append(s);
    }
    d->rightAxis->setVisible(anyRight);
    d->placeLegend();
}

void ChartWidget::setAxisTitle(ChartAxis axis, const QString &title) {
    (axis == ChartAxis::Left ? d->leftAxis : d->rightAxis)->setTitleText(title);
}

void ChartWidget::setTimeRange(qint64 t0, qint64 t1) {
    if (t1 <= t0)
        t1 = t0 + 1;
    if (t0 == d->t0 && t1 == d->t1)
        return;
    d->t0 = t0;
    d->t1 = t1;
    d->updateTimeTicks();
    d->placeOverlays();
    d->updatePlot();
}

void ChartWidget::setAxisRange(ChartAxis axis, double min, double max) {
    double *r = d->ranges[axis == ChartAxis::Left ? 0 : 1];
    if (r[0] == min && r[1] == max) // never true for the first call: the ranges start as NaN
        return;
    r[0] = min;
    r[1] = max;
    QValueAxis *a = axis == ChartAxis::Left ? d->leftAxis : d->rightAxis;
    a->setRange(min, max);
    d->updateValueTicks();
    d->updatePlot();
}

void ChartWidget::setPoints(int index, const QList<QPointF> &points) {
    if (index >= 0 && index < d->points.size()) {
        d->points[index] = points;
        d->updatePlot();
    }
}

void ChartWidget::showData(const ChartData &data) {
    for (int i = 0; i < d->points.size(); ++i)
        d->points[i] = data.points.value(i);
    setAxisRange(ChartAxis::Left, data.leftMin, data.leftMax);
    setAxisRange(ChartAxis::Right, data.rightMin, data.rightMax);
    setTimeRange(data.t0, qMax(data.t1, data.t0 + 1));
    d->updatePlot();
}

void ChartWidget::setMarkers(const QList<ChartMarker> &markers) {
    d->markers = markers;
    d->updatePlot();
}

void ChartWidget::setBands(const QList<ChartBand> &bands) {
    d->bands = bands;
    d->updatePlot();
}

void ChartWidget::setCrosshair(std::optional<qint64> timeMs) {
    d->crosshairTime = timeMs;
    d->placeOverlays();
}

void ChartWidget::setEmptyText(const QString &text) {
    d->emptyText->setText(text);
    d->emptyText->setVisible(!text.isEmpty());
    d->placeOverlays();
}

int ChartWidget::seriesCount() const {
    return int(d->styles.size());
}

QStringList ChartWidget::legendEntries() const {
    QStringList names;
    for (const QLineSeries *s : std::as_const(d->series))
        names.append(s->name());
    return names;
}

qsizetype ChartWidget::pointCount(int index) const {
    return d->points.value(index).size();
}

qint64 ChartWidget::timeStart() const {
    return d->t0;
}

qint64 ChartWidget::timeEnd() const {
    return d->t1;
}

QWidget *ChartWidget::plotSurface() const {
    return d->view->viewport();
}

double ChartWidget::valueTickStep(ChartAxis axis) const {
    return (axis == ChartAxis::Left ? d->leftAxis : d->rightAxis)->tickInterval();
}

QPair<double, double> ChartWidget::valueRange(ChartAxis axis) const {
    const double *r = d->ranges[axis == ChartAxis::Left ? 0 : 1];
    return {r[0], r[1]};
}

QFont ChartWidget::valueLabelFont() const {
    return d->leftAxis->labelsFont();
}

QRectF ChartWidget::plotArea() const {
    return d->plot();
}

int ChartWidget::plotWidth() const {
    return qMax(1, int(std::lround(d->plot().width())));
}

qint64 ChartWidget::timeAt(double x) const {
    const QRectF p = d->plot();
    const double fraction = p.width() > 0 ? (x - p.left()) / p.width() : 0;
    return d->t0 + qint64(std::llround(fraction * double(d->t1 - d->t0)));
}

double ChartWidget::xAt(qint64 timeMs) const {
    const QRectF p = d->plot();
    return p.left() + double(timeMs - d->t0) / double(d->t1 - d->t0) * p.width();
}

QPointF ChartWidget::seriesPosition(int index, const QPointF &value) const {
    if (index < 0 || index >= d->styles.size())
        return {};
    const QRectF p = d->plot();
    return {p.left() + (value.x() - double(d->t0)) / double(d->t1 - d->t0) * p.width(),
            d->yAt(d->styles.at(index).axis, value.y(), p)};
}

QString ChartWidget::markerTooltipAt(double x) const {
    QStringList tips;
    for (const ChartMarker &m : std::as_const(d->markers))
        if (m.timeMs >= d->t0 && m.timeMs < d->t1 && std::abs(xAt(m.timeMs) - x) <= kMarkerHitPx)
            tips.append(m.tooltip);
    if (tips.size() > 8) // a burst of events: the first ones and how many more
        tips = tips.mid(0, 8) << tr("… and %n more", nullptr, int(tips.size() - 8));
    return tips.join(QLatin1Char('\n'));
}

int ChartWidget::markerCount() const {
    return int(d->markers.size());
}

QImage ChartWidget::toImage() const {
    return d->view->grab().toImage();
}

QList<QRectF> ChartWidget::bandLabelRects() const {
    return d->bandLabels;
}

} // namespace tipscope::gui
