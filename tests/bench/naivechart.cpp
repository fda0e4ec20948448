#include "naivechart.h"

#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QLineSeries>
#include <QValueAxis>

namespace tipscope::bench {

struct NaiveChart::Parts {
    QChartView view;
    QChart *chart = new QChart;
    QValueAxis *time = new QValueAxis;
    QValueAxis *left = new QValueAxis;
    QValueAxis *right = new QValueAxis;
    QList<QLineSeries *> series;
};

NaiveChart::NaiveChart(const QList<NaiveSeries> &series, int width, int height)
    : d(std::make_unique<Parts>()) {
    d->chart->setAnimationOptions(QChart::NoAnimation);
    d->chart->addAxis(d->time, Qt::AlignBottom);
    d->chart->addAxis(d->left, Qt::AlignLeft);
    d->chart->addAxis(d->right, Qt::AlignRight);
    for (const NaiveSeries &s : series) {
        auto *line = new QLineSeries;
        line->setName(s.name);
        // The same one-pixel cosmetic pens as TipScope's chart: a wider pen would be stroked
        // into polygons and take minutes here.
        QPen pen(s.color, 1, s.style);
        pen.setCosmetic(true);
        line->setPen(pen);
        d->chart->addSeries(line);
        line->attachAxis(d->time);
        line->attachAxis(s.rightAxis ? d->right : d->left);
        d->series.append(line);
    }
    d->view.setChart(d->chart);
    d->view.resize(width, height);
    d->view.show();
    QCoreApplication::processEvents();
}

NaiveChart::~NaiveChart() = default;

double NaiveChart::showMs(const QList<QList<QPointF>> &points, qint64 t0, qint64 t1) {
    QElapsedTimer timer;
    timer.start();
    d->time->setRange(double(t0), double(t1));
    d->left->setRange(0, 400);
    d->right->setRange(0, 100);
    for (qsizetype i = 0; i < d->series.size() && i < points.size(); ++i)
        d->series.at(i)->replace(points.at(i));
    d->view.viewport()->repaint();
    return double(timer.nsecsElapsed()) / 1e6;
}

} // namespace tipscope::bench
