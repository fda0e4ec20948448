// ChartPlotView: paints what Qt Charts has no item for (alarm bands, event markers) in the
// foreground, and turns mouse and keyboard input into ChartWidget's requests.
#include "chartwidget_p.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPolygonF>
#include <QResizeEvent>
#include <QRubberBand>
#include <QToolTip>
#include <QVarLengthArray>
#include <QWheelEvent>
#include <cmath>

namespace tipscope::gui {

using model::ChartAxis;

namespace {
constexpr double kWheelZoomPerNotch = 0.8; // one wheel notch shows 80 % of the window
constexpr double kKeyPanFraction = 0.1;
constexpr int kMinBandPx = 4; // a smaller rubber band is a click, not a range

// The colour of a curve drawn as columns. Dashes cannot be drawn at that density, so a dashed or
// dotted curve is told apart by a paler colour (half way to white), as a dotted line looks.
QColor denseColor(const ChartSeriesStyle &style) {
    if (style.style == Qt::SolidLine)
        return style.color;
    return QColor((style.color.red() + 255) / 2, (style.color.green() + 255) / 2,
                  (style.color.blue() + 255) / 2);
}
} // namespace

ChartPlotView::ChartPlotView(QChart *chart, ChartWidget &owner)
    : QChartView(chart, &owner)
    , m_owner(owner)
    , m_rubberBand(new QRubberBand(QRubberBand::Rectangle, viewport())) {
    setObjectName(QStringLiteral("chartPlot"));
    setFrameShape(QFrame::NoFrame);
    setRubberBand(QChartView::NoRubberBand); // ours: the page owns the time window
    setRenderHint(QPainter::Antialiasing, false);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    viewport()->setMouseTracking(true);
    setAccessibleDescription(tr("Time chart. Wheel or plus and minus keys zoom, drag or arrow "
                                "keys pan, Shift+drag selects a range, double-click or Home "
                                "resets."));
}

// QChartView raises its own minimum size to the chart's at every resize and never lowers it. A
// chart whose margins were once wide (panes lining up while they were still being laid out) then
// held its pane that wide for good, and the wider pane asked for wider margins again: a layout
// that never settled. The page decides a pane's size; the chart follows it.
void ChartPlotView::resizeEvent(QResizeEvent *event) {
    QChartView::resizeEvent(event);
    setMinimumSize(0, 0);
}

void ChartPlotView::fitChart() {
    QResizeEvent again(size(), size());
    resizeEvent(&again);
}

double ChartPlotView::msPerPixel() const {
    const double width = m_owner.d->plot().width();
    return width > 0 ? double(m_owner.d->t1 - m_owner.d->t0) / width : 0;
}

void ChartPlotView::drawForeground(QPainter *painter, const QRectF &rect) {
    QChartView::drawForeground(painter, rect);
    const QRectF plot = m_owner.d->plot();
    if (plot.isEmpty())
        return;
    painter->save();
    drawValueGrid(*painter, plot);
    drawTimeAxis(*painter, plot);
    painter->setClipRect(plot);
    const QList<QPolygonF> curves = drawTraces(*painter, plot);
    drawBands(*painter, plot, curves);
    drawMarkers(*painter, plot);
    painter->restore();
}

// The left axis' grid: where Qt Charts would put it (dynamic ticks anchored at 0), in its pen.
void ChartPlotView::drawValueGrid(QPainter &painter, const QRectF &plot) const {
    const ChartWidgetPrivate &d = *m_owner.d;
    const double min = d.ranges[0][0], max = d.ranges[0][1];
    const double step = d.leftAxis->tickInterval();
    if (!d.leftAxis->isVisible() || !(max > min) || !(step > 0) || (max - min) / step > 1000)
        return;
    QVarLengthArray<QLineF, 32> lines;
    for (double v = std::ceil(min / step) * step; v <= max + step * 1e-9; v += step) {
        const double y = std::round(d.yAt(ChartAxis::Left, v, plot));
        lines.append(QLineF(plot.left(), y, plot.right(), y));
    }
    painter.setPen(d.leftAxis->gridLinePen());
    painter.drawLines(lines.constData(), int(lines.size()));
}

// Grid lines across the plot, tick marks under it and the labels below, in the value axes' pens
// and font so the three axes look alike.
void ChartPlotView::drawTimeAxis(QPainter &painter, const QRectF &plot) const {
    const ChartWidgetPrivate &d = *m_owner.d;
    const QList<ChartWidgetPrivate::TimeLabel> labels = d.timeLabels(plot);
    QVarLengthArray<QLineF, 32> grid, marks;
    for (const ChartWidgetPrivate::TimeLabel &l : labels) {
        grid.append(QLineF(l.x, plot.top(), l.x, plot.bottom()));
        marks.append(QLineF(l.x, plot.bottom(), l.x, plot.bottom() + 5));
    }
    painter.setPen(d.leftAxis->gridLinePen());
    painter.drawLines(grid.constData(), int(grid.size()));
    painter.setPen(d.leftAxis->linePen());
    painter.drawLines(marks.constData(), int(marks.size()));
    painter.setFont(d.tickTextFont);
    painter.setPen(QPen(d.leftAxis->labelsBrush(), 1));
    for (const ChartWidgetPrivate::TimeLabel &l : labels)
        painter.drawStaticText(l.rect.topLeft(), d.tickTexts.at(l.index));
}

QList<QPolygonF> ChartPlotView::drawTraces(QPainter &painter, const QRectF &plot) const {
    const ChartWidgetPrivate &d = *m_owner.d;
    const double xScale = plot.width() / double(d.t1 - d.t0);
    // Off-plot points are clipped; bounding them first keeps the pixel arithmetic in range.
    const double above = plot.top() - 1;
    const double below = plot.bottom() + 1;
    // Power and speed first: a day of power bursts fills whole columns, and the temperatures
    // must stay visible on top of it.
    QList<qsizetype> order;
    for (ChartAxis axis : {ChartAxis::Right, ChartAxis::Left})
        for (qsizetype i = 0; i < d.points.size() && i < d.styles.size(); ++i)
            if (d.styles.at(i).axis == axis)
                order.append(i);
    QList<QPolygonF> drawn;
    QPolygonF line;
    for (qsizetype i : std::as_const(order)) {
        const ChartSeriesStyle &style = d.styles.at(i);
        const QList<QPointF> &points = d.points.at(i);
        const bool dense = points.size() > plot.width();
        const auto draw = [&] {
            if (dense)
                drawColumns(painter, line, denseColor(style));
            else if (!line.isEmpty())
                painter.drawPolyline(line);
            if (!line.isEmpty())
                drawn.append(line);
            line.clear();
        };
        painter.setPen(tracePen(style));
        line.clear();
        line.reserve(points.size());
        for (const QPointF &p : points) {
            // A point without a value is a gap in the data: the curve stops and starts again.
            if (!std::isfinite(p.y())) {
                draw();
                continue;
            }
            const QPointF pixel(plot.left() + (p.x() - double(d.t0)) * xScale,
                                d.yAt(style.axis, p.y(), plot));
            if (std::isfinite(pixel.x()) && std::isfinite(pixel.y()))
                line.append(QPointF(qBound(plot.left() - 2, pixel.x(), plot.right() + 2),
                                    qBound(above, pixel.y(), below)));
        }
        draw();
    }
    return drawn;
}

// A min/max curve denser than the pixels is a vertical run per pixel column. Drawn as one
// opaque 1-pixel rectangle per column it costs a memory fill per row; as a polyline, every
// spike was stroked twice (up and down) a pixel at a time, which for a day of power readings
// took 16 ms a frame (tipscope-bench chart). Patterned or translucent fills fall off the fast
// path (ten times slower than stroking), so the column is opaque.
void ChartPlotView::drawColumns(QPainter &painter, const QPolygonF &line,
                                const QColor &color) const {
    bool open = false;
    int x = 0;
    double low = 0;
    double high = 0;
    double last = 0;
    const auto flush = [&] {
        const int top = int(std::floor(low));
        painter.fillRect(QRect(x, top, 1, int(std::floor(high)) - top + 1), color);
    };
    for (const QPointF &p : line) {
        const int px = int(std::floor(p.x()));
        if (!open || px != x) {
            // A column joins the one before it, where there is one: a column with no sample
            // (a gap in the data) stays empty.
            const bool joined = open && px == x + 1;
            if (open)
                flush();
            low = high = joined ? last : p.y();
            x = px;
            open = true;
        }
        low = qMin(low, p.y());
        high = qMax(high, p.y());
        last = p.y();
    }
    if (open)
        flush();
}

void ChartPlotView::drawBands(QPainter &painter, const QRectF &plot,
                              const QList<QPolygonF> &curves) const {
    m_owner.d->bandLabels.clear();
    for (const ChartBand &b : std::as_const(m_owner.d->bands)) {
        const double top =
            std::isfinite(b.high) ? m_owner.d->yAt(b.axis, b.high, plot) : plot.top();
        const double bottom =
            std::isfinite(b.low) ? m_owner.d->yAt(b.axis, b.low, plot) : plot.bottom();
        QColor fill = b.color;
        fill.setAlpha(28);
        painter.fillRect(QRectF(plot.left(), top, plot.width(), bottom - top), fill);
        const double edge = b.labelAtLow ? bottom : top;
        if (edge < plot.top() || edge > plot.bottom())
            continue;
        painter.setPen(QPen(b.color, 1, Qt::DashDotLine));
        painter.drawLine(QPointF(plot.left(), edge), QPointF(plot.right(), edge));
        if (const auto place = bandLabelPlace(b, edge, plot, painter.font(), curves)) {
            painter.drawText(*place, Qt::AlignLeft | Qt::AlignVCenter, b.label);
            m_owner.d->bandLabels.append(*place);
        }
    }
}

namespace {
// Whether any segment of the curves passes through `rect`.
bool crossesAny(const QRectF &rect, const QList<QPolygonF> &curves) {
    const QLineF edges[] = {{rect.topLeft(), rect.topRight()},
                            {rect.topRight(), rect.bottomRight()},
                            {rect.bottomRight(), rect.bottomLeft()},
                            {rect.bottomLeft(), rect.topLeft()}};
    for (const QPolygonF &curve : curves) {
        if (!curve.boundingRect().adjusted(-1, -1, 1, 1).intersects(rect))
            continue;
        for (qsizetype i = 0; i < curve.size(); ++i) {
            if (rect.contains(curve.at(i)))
                return true;
            if (i == 0)
                continue;
            const QLineF segment(curve.at(i - 1), curve.at(i));
            for (const QLineF &e : edges)
                if (segment.intersects(e, nullptr) == QLineF::BoundedIntersection)
                    return true;
        }
    }
    return false;
}
} // namespace

// A band's label goes beside its limit line, inside the band first, at the left, the middle or
// the right, wherever no curve passes; when every place is crossed it is left out (the shading
// and the line still show the limit) rather than hide the curve a person is watching.
std::optional<QRectF> ChartPlotView::bandLabelPlace(const ChartBand &band, double edge,
                                                    const QRectF &plot, const QFont &font,
                                                    const QList<QPolygonF> &curves) const {
    const QFontMetricsF metrics(font);
    const QSizeF size(metrics.horizontalAdvance(band.label) + 4, metrics.height());
    const double inside = band.labelAtLow ? edge - 2 - size.height() : edge + 2;
    const double outside = band.labelAtLow ? edge + 2 : edge - 2 - size.height();
    for (const double y : {inside, outside}) {
        for (const double x : {plot.left() + 4, plot.center().x() - size.width() / 2,
                               plot.right() - 4 - size.width()}) {
            const QRectF rect(QPointF(x, y), size);
            if (plot.contains(rect) && !crossesAny(rect.adjusted(-2, -1, 2, 1), curves))
                return rect;
        }
    }
    return std::nullopt;
}

void ChartPlotView::drawMarkers(QPainter &painter, const QRectF &plot) const {
    const ChartWidgetPrivate &d = *m_owner.d;
    for (const ChartMarker &m : std::as_const(d.markers)) {
        if (m.timeMs < d.t0 || m.timeMs >= d.t1)
            continue;
        const double x = plot.left() + double(m.timeMs - d.t0) / double(d.t1 - d.t0) * plot.width();
        QColor line = m.color;
        line.setAlpha(150);
        painter.setPen(QPen(line, 1, Qt::DashLine));
        painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        // A flag at the top edge, where the cursor finds the tooltip.
        const QPointF flag[] = {{x - 4, plot.top()}, {x + 4, plot.top()}, {x, plot.top() + 7}};
        painter.setPen(Qt::NoPen);
        painter.setBrush(m.color);
        painter.drawPolygon(flag, 3);
    }
}

void ChartPlotView::mousePressEvent(QMouseEvent *event) {
    m_pressPos = m_lastPos = event->position().toPoint();
    const bool band = event->button() == Qt::RightButton ||
                      (event->button() == Qt::LeftButton && event->modifiers() & Qt::ShiftModifier);
    m_drag = band ? Drag::Band : event->button() == Qt::LeftButton ? Drag::Pan : Drag::None;
    if (m_drag == Drag::Band) {
        const QRectF plot = m_owner.d->plot();
        m_rubberBand->setGeometry(QRect(m_pressPos.x(), int(plot.top()), 0, int(plot.height())));
        m_rubberBand->show();
    } else if (m_drag == Drag::Pan) {
        viewport()->setCursor(Qt::ClosedHandCursor);
    }
    event->accept();
}

void ChartPlotView::mouseMoveEvent(QMouseEvent *event) {
    const QPoint pos = event->position().toPoint();
    const QRectF plot = m_owner.d->plot();
    if (m_drag == Drag::Pan && pos.x() != m_lastPos.x()) {
        // Dragging right brings earlier times into view.
        Q_EMIT m_owner.panRequested(
            -qint64(std::llround((pos.x() - m_lastPos.x()) * msPerPixel())));
    } else if (m_drag == Drag::Band) {
        const int x = qBound(int(plot.left()), pos.x(), int(plot.right()));
        m_rubberBand->setGeometry(QRect(QPoint(qMin(x, m_pressPos.x()), int(plot.top())),
                                        QSize(std::abs(x - m_pressPos.x()), int(plot.height()))));
    }
    m_lastPos = pos;
    if (plot.contains(event->position())) {
        Q_EMIT m_owner.hovered(m_owner.timeAt(event->position().x()));
        const QString tip = m_owner.markerTooltipAt(event->position().x());
        if (tip.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(event->globalPosition().toPoint(), tip, viewport());
    } else {
        Q_EMIT m_owner.left();
    }
    event->accept();
}

void ChartPlotView::mouseReleaseEvent(QMouseEvent *event) {
    if (m_drag == Drag::Band) {
        m_rubberBand->hide();
        const QRect band = m_rubberBand->geometry();
        if (band.width() >= kMinBandPx)
            Q_EMIT m_owner.rangeSelected(m_owner.timeAt(band.left()), m_owner.timeAt(band.right()));
    }
    viewport()->unsetCursor();
    m_drag = Drag::None;
    event->accept();
}

void ChartPlotView::mouseDoubleClickEvent(QMouseEvent *event) {
    Q_EMIT m_owner.resetRequested();
    event->accept();
}

void ChartPlotView::wheelEvent(QWheelEvent *event) {
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0)
        Q_EMIT m_owner.zoomRequested(std::pow(kWheelZoomPerNotch, notches),
                                     m_owner.timeAt(event->position().x()));
    event->accept();
}

void ChartPlotView::keyPressEvent(QKeyEvent *event) {
    const ChartWidgetPrivate &d = *m_owner.d;
    const qint64 middle = d.t0 + (d.t1 - d.t0) / 2;
    const qint64 step = qint64(double(d.t1 - d.t0) * kKeyPanFraction);
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        Q_EMIT m_owner.zoomRequested(kWheelZoomPerNotch, middle);
        break;
    case Qt::Key_Minus:
        Q_EMIT m_owner.zoomRequested(1 / kWheelZoomPerNotch, middle);
        break;
    case Qt::Key_Left:
        Q_EMIT m_owner.panRequested(-step);
        break;
    case Qt::Key_Right:
        Q_EMIT m_owner.panRequested(step);
        break;
    case Qt::Key_Home:
        Q_EMIT m_owner.resetRequested();
        break;
    default:
        QChartView::keyPressEvent(event);
        return;
    }
    event->accept();
}

void ChartPlotView::leaveEvent(QEvent *event) {
    Q_EMIT m_owner.left();
    QChartView::leaveEvent(event);
}

} // namespace tipscope::gui
