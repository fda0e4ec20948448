// ChartWidget's insides: the Qt Charts objects and the view that paints the markers and bands
// and turns mouse and keyboard input into the widget's requests. Private to chartwidget.cpp and
// chartplotview.cpp; nothing else includes Qt Charts.
#pragma once

#include "chartwidget.h"

#include <QChartView>
#include <QGraphicsLineItem>
#include <QGraphicsSimpleTextItem>
#include <QLineSeries>
#include <QStaticText>
#include <QValueAxis>

class QRubberBand;

namespace tipscope::gui {

// The pen of a curve, for the plot and for its legend entry.
[[nodiscard]] QPen tracePen(const ChartSeriesStyle &style);

class ChartPlotView : public QChartView {
    Q_OBJECT
public:
    ChartPlotView(QChart *chart, ChartWidget &owner);
    // After the chart's margins changed: the chart takes the view's size again.
    void fitChart();

protected:
    void resizeEvent(QResizeEvent *event) override;
    void drawForeground(QPainter *painter, const QRectF &rect) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void leaveEvent(QEvent *event) override;

private:
    enum class Drag { None, Pan, Band };

    // The curves, as polylines in the plot's pixels. QLineSeries is not used for them: for
    // every new set of points it builds a path and strokes a hover outline of it, which cost
    // more than painting the curve itself.
    void drawValueGrid(QPainter &painter, const QRectF &plot) const;
    void drawTimeAxis(QPainter &painter, const QRectF &plot) const;
    // Returns the curves as drawn, in pixels, so labels can keep off them.
    [[nodiscard]] QList<QPolygonF> drawTraces(QPainter &painter, const QRectF &plot) const;
    void drawColumns(QPainter &painter, const QPolygonF &line, const QColor &color) const;
    void drawBands(QPainter &painter, const QRectF &plot, const QList<QPolygonF> &curves) const;
    void drawMarkers(QPainter &painter, const QRectF &plot) const;
    [[nodiscard]] std::optional<QRectF> bandLabelPlace(const ChartBand &band, double edge,
                                                       const QRectF &plot, const QFont &font,
                                                       const QList<QPolygonF> &curves) const;
    [[nodiscard]] double msPerPixel() const;

    ChartWidget &m_owner;
    Drag m_drag = Drag::None;
    QPoint m_pressPos;
    QPoint m_lastPos;
    QRubberBand *m_rubberBand;
};

class ChartWidgetPrivate {
public:
    explicit ChartWidgetPrivate(ChartWidget &owner);

    // Plot area in scene coordinates, which are the view's viewport coordinates (the chart
    // fills the scene at the origin, unscaled).
    [[nodiscard]] QRectF plot() const { return chart->plotArea(); }
    [[nodiscard]] double yAt(model::ChartAxis axis, double value, const QRectF &plot) const;
    void placeOverlays();
    void applyMargins();
    void showTitle();
    void placeLegend();
    void updatePlot();
    // Ticks on round times (every 10 s, 1 min, 1 h...), which QDateTimeAxis cannot do: its
    // ticks divide the range evenly, so a moving window would show 03:10:47, 03:11:30...
    void updateTimeTicks();
    // Each value axis' tick step for its range and the plot's height: round values, at most
    // five steps, fewer in a short pane so its labels never crowd (Qt Charts elides crowded
    // vertical labels to "...").
    void updateValueTicks();
    // Height of the band under the plot that holds the time labels.
    [[nodiscard]] int timeLabelStrip() const;
    struct TimeLabel {
        double x;        // the tick, in scene pixels
        QRectF rect;     // where its text goes
        qsizetype index; // into ticks and tickTexts
    };
    // The ticks inside the plot and their labels' places, the texts laid out if they changed.
    [[nodiscard]] QList<TimeLabel> timeLabels(const QRectF &plot) const;

    QChart *chart;
    ChartPlotView *view = nullptr;
    QValueAxis *timeAxis = nullptr;
    QValueAxis *leftAxis = nullptr;
    QValueAxis *rightAxis = nullptr;
    QList<QLineSeries *> series; // the legend's entries, never given points
    QList<ChartSeriesStyle> styles;
    QList<QList<QPointF>> points; // per series, in display units against time in ms
    QGraphicsLineItem *crosshair;
    QGraphicsSimpleTextItem *emptyText;
    QString title;
    bool compact = false;
    bool titleShown = true;
    // Extra room beside the plot so that panes stacked on one page start and end their plots at
    // the same x (see alignPlots()).
    int padLeft = 0;
    int padRight = 0;
    // The padding the plot area was last laid out with. Qt Charts lays out in a posted event,
    // so between new margins and that layout the plot area is the old one: its natural insets
    // are the old plot less the old padding, never less the new.
    int laidOutPadLeft = 0;
    int laidOutPadRight = 0;
    // Where the alarm bands' labels were drawn in the last paint (tests).
    mutable QList<QRectF> bandLabels;
    qint64 t0 = 0;
    qint64 t1 = 1;
    double ranges[2][2] = {{qQNaN(), qQNaN()}, {qQNaN(), qQNaN()}}; // [axis][min, max]
    QList<qint64> ticks; // the time axis' current ticks, and their labels
    QStringList tickLabels;
    // The labels laid out once for as long as they stay: shaping them again on every frame was
    // a visible share of a following chart's painting.
    mutable QList<QStaticText> tickTexts;
    mutable QFont tickTextFont;
    // Where the time labels were last asked to be repainted: a frame repaints their old places
    // and their new ones, not the whole strip, whose ends hold the value axes' first labels
    // (rich text, dear to paint again).
    QRegion timeLabelsRegion;
    qint64 tickStep = 0;
    // The local clock's offset from UTC, looked up once per quarter hour of the window's start
    // (a time zone lookup per frame was another share of it).
    qint64 utcOffsetMs = 0;
    qint64 utcOffsetQuarter = -1;
    std::optional<qint64> crosshairTime;
    QList<ChartMarker> markers;
    QList<ChartBand> bands;
};

} // namespace tipscope::gui
