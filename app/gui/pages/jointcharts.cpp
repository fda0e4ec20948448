#include "jointcharts.h"

#include "model/joints/jointtable.h"

#include <QLocale>
#include <QPainter>
#include <QPainterPath>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
constexpr int kPad = 6;
constexpr int kMinPlotHeight = 90;
constexpr int kMinWidth = 280;
constexpr int kMarker = 3;
// Distinct on light and dark backgrounds, and for the common colour-vision deficiencies.
const QColor kToolColours[] = {QColor(0, 114, 178),   QColor(213, 94, 0),  QColor(0, 158, 115),
                               QColor(204, 121, 167), QColor(230, 159, 0), QColor(86, 180, 233)};

// The plot's rectangle under the caption, with room on the left for the value labels and
// under it for the axis labels.
QRect plotRect(const QWidget &w, int leftLabelWidth) {
    const int line = w.fontMetrics().height();
    return w.rect().adjusted(kPad + leftLabelWidth + kPad, kPad + line + kPad, -kPad,
                             -(kPad + line + kPad));
}

void drawCaption(QPainter &p, const QWidget &w, const QString &caption) {
    p.setPen(w.palette().color(QPalette::WindowText));
    const QRect line(kPad, kPad, w.width() - 2 * kPad, w.fontMetrics().height());
    p.drawText(line, Qt::AlignLeft | Qt::AlignVCenter,
               w.fontMetrics().elidedText(caption, Qt::ElideRight, line.width()));
}

void drawNothing(QPainter &p, const QWidget &w, const QString &text) {
    p.setPen(w.palette().color(QPalette::PlaceholderText));
    p.drawText(w.rect(), Qt::AlignCenter | Qt::TextWordWrap, text);
}

// The value axis: its top value at the top left of the plot, 0 at the bottom.
void drawValueAxis(QPainter &p, const QWidget &w, const QRect &plot, const QString &top) {
    p.setPen(w.palette().color(QPalette::WindowText));
    const QRect labels(kPad, plot.top() - w.fontMetrics().height() / 2, plot.left() - 2 * kPad,
                       plot.height() + w.fontMetrics().height());
    p.drawText(labels, Qt::AlignRight | Qt::AlignTop, top);
    p.drawText(labels, Qt::AlignRight | Qt::AlignBottom, QStringLiteral("0"));
    p.setPen(w.palette().color(QPalette::Mid));
    p.drawLine(plot.bottomLeft(), plot.bottomRight());
    p.drawLine(plot.bottomLeft(), plot.topLeft());
}
} // namespace

RecoveryHistogramView::RecoveryHistogramView(QWidget *parent)
    : QWidget(parent) {
    setAccessibleName(tr("Histogram of recovery times"));
}

void RecoveryHistogramView::setHistogram(const RecoveryHistogram &histogram) {
    m_histogram = histogram;
    setAccessibleDescription(caption());
    update();
}

QString RecoveryHistogramView::caption() const {
    int recovered = 0;
    for (const int n : m_histogram.counts)
        recovered += n;
    const QString text = tr("Recovery time of %n joint(s)", nullptr, recovered);
    return m_histogram.notRecovered == 0
               ? text
               : tr("%1 (%n did not recover)", nullptr, m_histogram.notRecovered).arg(text);
}

QSize RecoveryHistogramView::minimumSizeHint() const {
    return {kMinWidth, kMinPlotHeight + 2 * (fontMetrics().height() + 2 * kPad)};
}

void RecoveryHistogramView::paintEvent(QPaintEvent *event) {
    Q_UNUSED(event);
    QPainter p(this);
    drawCaption(p, *this, caption());
    const int top = m_histogram.maxCount();
    if (top == 0) {
        drawNothing(p, *this, tr("No recovered joints listed"));
        return;
    }
    const QString topText = QLocale().toString(top);
    const QRect plot = plotRect(*this, fontMetrics().horizontalAdvance(topText));
    drawValueAxis(p, *this, plot, topText);
    const int bins = int(m_histogram.counts.size());
    const double binWidth = double(plot.width()) / bins;
    p.setPen(Qt::NoPen);
    p.setBrush(palette().color(QPalette::Highlight));
    for (int i = 0; i < bins; ++i) {
        const double h = double(plot.height()) * m_histogram.counts.at(i) / top;
        p.drawRect(QRectF(plot.left() + i * binWidth + 1, plot.bottom() - h, binWidth - 2, h));
    }
    // Seconds under the bin edges, as many as fit without touching.
    p.setPen(palette().color(QPalette::WindowText));
    const QString widest = JointTableModel::secondsText(m_histogram.binMs * bins);
    const int every = qMax(1, int((fontMetrics().horizontalAdvance(widest) + kPad) / binWidth) + 1);
    for (int i = 0; i <= bins; i += every) {
        const QString label = JointTableModel::secondsText(m_histogram.binMs * i);
        const int x = plot.left() + int(i * binWidth);
        const int half = fontMetrics().horizontalAdvance(label) / 2;
        if (x + half > width() - kPad)
            break;
        p.drawText(QRect(x - half, plot.bottom() + kPad / 2, 2 * half + 2, fontMetrics().height()),
                   Qt::AlignCenter, label);
    }
}

RecoveryTrendView::RecoveryTrendView(QWidget *parent)
    : QWidget(parent) {
    setAccessibleName(tr("Daily median recovery time per tool"));
}

void RecoveryTrendView::setTrends(const QList<ToolTrend> &trends) {
    m_trends = trends;
    setAccessibleDescription(caption());
    update();
}

QString RecoveryTrendView::caption() const {
    QStringList tools;
    for (const ToolTrend &t : m_trends)
        tools.append(t.tool);
    return tools.isEmpty() ? tr("Median recovery time per day")
                           : QStringLiteral("%1 %2").arg(tr("Median recovery time per day:"),
                                                         tools.join(QStringLiteral(", ")));
}

QSize RecoveryTrendView::minimumSizeHint() const {
    return {kMinWidth, kMinPlotHeight + 2 * (fontMetrics().height() + 2 * kPad)};
}

void RecoveryTrendView::paintEvent(QPaintEvent *event) {
    Q_UNUSED(event);
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    if (m_trends.isEmpty()) {
        drawCaption(p, *this, caption());
        drawNothing(p, *this, tr("No recovered joints listed"));
        return;
    }
    QDate first = m_trends.first().days.first().day;
    QDate last = first;
    qint64 top = 0;
    for (const ToolTrend &t : m_trends)
        for (const DailyRecovery &d : t.days) {
            first = qMin(first, d.day);
            last = qMax(last, d.day);
            top = qMax(top, d.medianMs);
        }
    // Some room above the highest point, so it does not sit on the edge.
    top += top / 10;
    const QString topText = JointTableModel::secondsText(top);
    const QRect plot = plotRect(*this, fontMetrics().horizontalAdvance(topText));
    drawValueAxis(p, *this, plot, topText);
    const qint64 span = qMax<qint64>(1, first.daysTo(last));
    const auto at = [&](const DailyRecovery &d) {
        const double x = first == last
                             ? plot.center().x()
                             : plot.left() + plot.width() * double(first.daysTo(d.day)) / span;
        return QPointF(x,
                       plot.bottom() - plot.height() * double(d.medianMs) / qMax<qint64>(1, top));
    };
    // The caption names each tool in its line's colour.
    const QString prefix = tr("Median recovery time per day:");
    const int baseline = kPad + fontMetrics().ascent();
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QPoint(kPad, baseline), prefix);
    int legendX = kPad + fontMetrics().horizontalAdvance(prefix) + kPad;
    for (int i = 0; i < m_trends.size(); ++i) {
        const QColor colour = kToolColours[i % std::size(kToolColours)];
        QPainterPath path;
        for (const DailyRecovery &d : m_trends.at(i).days) {
            const QPointF point = at(d);
            path.isEmpty() ? path.moveTo(point) : path.lineTo(point);
            p.setBrush(colour);
            p.setPen(Qt::NoPen);
            p.drawEllipse(point, kMarker, kMarker);
        }
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(colour, 2));
        p.drawPath(path);
        const QString &name = m_trends.at(i).tool;
        p.drawText(QPoint(legendX, baseline), name);
        legendX += fontMetrics().horizontalAdvance(name) + 2 * kPad;
    }
    p.setPen(palette().color(QPalette::WindowText));
    const QLocale locale;
    const QRect axis(plot.left(), plot.bottom() + kPad / 2, plot.width(), fontMetrics().height());
    p.drawText(axis, Qt::AlignLeft | Qt::AlignVCenter,
               locale.toString(first, QLocale::ShortFormat));
    if (last != first)
        p.drawText(axis, Qt::AlignRight | Qt::AlignVCenter,
                   locale.toString(last, QLocale::ShortFormat));
}

} // namespace tipscope::gui
