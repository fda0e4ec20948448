// The naive chart of the chart benchmark: what a first attempt with Qt Charts looks like. Every
// sample of the window goes to a QLineSeries (one replace() per series) on a plain QChartView,
// and Qt Charts maps, strokes and paints them all. TipScope's chart is measured against it.
#pragma once

#include <QColor>
#include <QList>
#include <QPointF>
#include <QString>
#include <memory>

namespace tipscope::bench {

struct NaiveSeries {
    QString name;
    QColor color;
    Qt::PenStyle style = Qt::SolidLine;
    bool rightAxis = false;
};

class NaiveChart {
public:
    NaiveChart(const QList<NaiveSeries> &series, int width, int height);
    ~NaiveChart();

    // Hands every point over and paints once; the milliseconds it took.
    double showMs(const QList<QList<QPointF>> &points, qint64 t0, qint64 t1);

private:
    struct Parts;
    std::unique_ptr<Parts> d;
};

} // namespace tipscope::bench
