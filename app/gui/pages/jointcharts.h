// Two small charts of the Joints page, drawn with QPainter (Qt Charts stays inside ChartWidget):
// RecoveryHistogramView, how the recovery times of the listed joints spread, and
// RecoveryTrendView, each tool's daily median recovery time, so a tip that slowly wears shows
// as a rising line. Both only draw what they are given; the page computes it (jointstats.h).
// Each states its subject and counts in words above the plot, and says so when there is nothing
// to draw rather than showing empty axes.
#pragma once

#include "model/joints/jointstats.h"

#include <QWidget>

namespace tipscope::gui {

class RecoveryHistogramView : public QWidget {
    Q_OBJECT
public:
    explicit RecoveryHistogramView(QWidget *parent = nullptr);
    void setHistogram(const model::RecoveryHistogram &histogram);
    [[nodiscard]] const model::RecoveryHistogram &histogram() const { return m_histogram; }
    // The line above the plot ("Recovery time of 42 joints (3 did not recover)").
    [[nodiscard]] QString caption() const;
    [[nodiscard]] QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    model::RecoveryHistogram m_histogram;
};

class RecoveryTrendView : public QWidget {
    Q_OBJECT
public:
    explicit RecoveryTrendView(QWidget *parent = nullptr);
    void setTrends(const QList<model::ToolTrend> &trends);
    [[nodiscard]] const QList<model::ToolTrend> &trends() const { return m_trends; }
    [[nodiscard]] QString caption() const;
    [[nodiscard]] QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QList<model::ToolTrend> m_trends;
};

} // namespace tipscope::gui
