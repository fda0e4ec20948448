// ChartWidget: one time chart, and the only place in TipScope that uses Qt Charts (deprecated
// from Qt 6.10 in favour of Qt Graphs): every Qt Charts type stays in chartwidget.cpp,
// chartplotview.cpp and chartwidget_p.h, so a move to Qt Graphs rewrites these files and nothing
// else. This header speaks in plain Qt types.
//
// The widget holds no history. The page gives it, per redraw, the points of each series (already
// decimated to the plot's width, see ChartFrame), the time range, the axis ranges (showData()),
// the event markers and the alarm bands. Qt Charts draws the axes, grid and legend; the curves
// are painted by the widget itself (QLineSeries builds a path and strokes a hover outline for
// every new set of points, which cost more than the drawing). A curve with fewer points than
// the plot has pixel columns is a one-pixel polyline in its pen style; a denser one (a min/max
// zigzag) is one opaque vertical run per pixel column, paler when its style is dashed or
// dotted, and power curves are drawn beneath temperatures. No animations and no OpenGL.
//
// What people do with the mouse and keyboard comes back as requests, not as a changed view: the
// page owns the time window (ChartViewport) and redraws. Wheel: zoomRequested() about the
// cursor; left drag: panRequested(); Shift+drag or right drag: rangeSelected() (rubber band);
// double-click or Home: resetRequested(); +/- and the arrow keys zoom and pan from the keyboard.
// Hovering the plot reports the time under the cursor (hovered(), left()) for the crosshair and
// shows a marker's tooltip when the cursor is on it.
#pragma once

#include "model/chart/chartseries.h"

#include <QImage>
#include <QWidget>
#include <memory>
#include <optional>

namespace tipscope::gui {

struct ChartSeriesStyle {
    QString name;
    QColor color;
    Qt::PenStyle style = Qt::SolidLine;
    model::ChartAxis axis = model::ChartAxis::Left;
};

struct ChartMarker {
    qint64 timeMs = 0;
    QColor color;
    QString tooltip;
};

// A value range shaded on one axis (an alarm zone); the edges may lie beyond the axis range.
struct ChartBand {
    model::ChartAxis axis = model::ChartAxis::Left;
    double low = 0;
    double high = 0;
    QColor color;
    QString label; // drawn at the band's inner edge ("P1 HA 450 °C")
    bool labelAtLow = true;
};

// Everything one redraw changes, applied at once by ChartWidget::showData().
struct ChartData {
    qint64 t0 = 0;
    qint64 t1 = 1;
    double leftMin = 0;
    double leftMax = 1;
    double rightMin = 0;
    double rightMax = 100;
    QList<QList<QPointF>> points; // one list per series, x in ms since the epoch
};

class ChartWidgetPrivate;

class ChartWidget : public QWidget {
    Q_OBJECT
public:
    explicit ChartWidget(QWidget *parent = nullptr);
    ~ChartWidget() override;

    void setTitle(const QString &title);
    // Whether the title is drawn above the plot (an exported image); on screen the page names
    // what is shown, and the title stays the accessible name. Shown by default.
    void setTitleShown(bool shown);
    // For short panes: no title (it stays the accessible name) and the legend at the side.
    void setCompact(bool compact);
    // The curves, and the legend's entries when they should not be one per curve (ports
    // overlaid: a colour per port and a dash per kind of value, rather than every pair).
    void setSeries(const QList<ChartSeriesStyle> &series,
                   const QList<ChartSeriesStyle> &legend = {});
    void setAxisTitle(model::ChartAxis axis, const QString &title); // an empty right title hides it
    void setTimeRange(qint64 t0, qint64 t1);
    void setAxisRange(model::ChartAxis axis, double min, double max);
    // Replaces the points of series `index` (x: ms since the epoch) with one replace().
    void setPoints(int index, const QList<QPointF> &points);
    // A whole redraw: ranges and every series' points (one replace() each), ordered so that Qt
    // Charts maps each series to the screen once rather than once per change (see the .cpp).
    void showData(const ChartData &data);
    void setMarkers(const QList<ChartMarker> &markers);
    void setBands(const QList<ChartBand> &bands);
    // The crosshair line, shared by every pane of a page; nullopt hides it.
    void setCrosshair(std::optional<qint64> timeMs);
    // A note over an empty plot ("No samples in this window"); empty hides it.
    void setEmptyText(const QString &text);

    [[nodiscard]] int seriesCount() const;
    [[nodiscard]] QStringList legendEntries() const;
    [[nodiscard]] qsizetype pointCount(int index) const;
    [[nodiscard]] qint64 timeStart() const;
    [[nodiscard]] qint64 timeEnd() const;
    // The surface that paints the chart and takes the mouse; the coordinates below are its.
    [[nodiscard]] QWidget *plotSurface() const;
    // The plot area, and its width in whole pixels (at least 1).
    [[nodiscard]] QRectF plotArea() const;
    [[nodiscard]] int plotWidth() const;
    // The step between the labelled values of an axis, and the font of those labels.
    [[nodiscard]] double valueTickStep(model::ChartAxis axis) const;
    [[nodiscard]] QPair<double, double> valueRange(model::ChartAxis axis) const;
    [[nodiscard]] QFont valueLabelFont() const;
    [[nodiscard]] qint64 timeAt(double x) const;
    [[nodiscard]] double xAt(qint64 timeMs) const;
    // Where Qt Charts itself draws `value` (x in ms) of series `index`: tests hold the
    // crosshair's mapping to the chart's own.
    [[nodiscard]] QPointF seriesPosition(int index, const QPointF &value) const;
    // The tooltip of the markers within a few pixels of `x`, or empty.
    [[nodiscard]] QString markerTooltipAt(double x) const;
    [[nodiscard]] int markerCount() const;
    // The chart as an image at its current size (PNG export).
    [[nodiscard]] QImage toImage() const;
    // Where the alarm bands' labels were drawn in the last paint: never over a curve.
    [[nodiscard]] QList<QRectF> bandLabelRects() const;

    // The room Qt Charts gives the axes and legend left and right of the plot, in pixels, and
    // extra room so that the plot starts `left` and ends `right` pixels from the widget's edges
    // (never less than its natural room). See alignPlots().
    [[nodiscard]] QPair<int, int> naturalPlotInsets() const;
    void alignPlot(int left, int right);
    // Whether the chart has been given room enough for a plot: until then (a pane just made, not
    // yet laid out, whose plot Qt Charts squeezed to its minimum) its insets say nothing about
    // its axes, and padding it or from it would feed the layout back into itself.
    [[nodiscard]] bool hasRoom() const;
    static constexpr int kMinAlignedPlotPx = 100;

Q_SIGNALS:
    void hovered(qint64 timeMs);
    void left();
    void zoomRequested(double factor, qint64 anchorMs);
    void panRequested(qint64 deltaMs);
    void rangeSelected(qint64 t0, qint64 t1);
    void resetRequested();
    void plotResized();

private:
    friend class ChartWidgetPrivate;
    friend class ChartPlotView;
    std::unique_ptr<ChartWidgetPrivate> d;
};

// Charts stacked in one column share one time axis: each gets the widest natural room of them
// all on either side, so the same instant sits at the same x in every one of them. Call it
// again when a chart's plot area changes (ChartWidget::plotResized).
void alignPlots(const QList<ChartWidget *> &charts);

} // namespace tipscope::gui
