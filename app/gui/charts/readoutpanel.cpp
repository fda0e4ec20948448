#include "readoutpanel.h"

#include "model/chart/chartframe.h"

#include <QEvent>
#include <QPainter>

namespace tipscope::gui {

namespace {
constexpr int kGap = 18; // between the instant and the cells, and between columns
} // namespace

ReadoutPanel::ReadoutPanel(QWidget *parent)
    : QWidget(parent) {
    QSizePolicy policy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    policy.setHeightForWidth(true);
    setSizePolicy(policy);
}

void ReadoutPanel::setTemplate(const QStringList &cells) {
    m_template = cells;
    m_cellWidth = 0;
    m_cellCount = int(cells.size());
    learnWidths(cells);
}

void ReadoutPanel::learnWidths(const QStringList &cells) {
    const int before = m_cellWidth;
    const int beforeCount = m_cellCount;
    for (const QString &cell : cells)
        m_cellWidth = qMax(m_cellWidth, fontMetrics().horizontalAdvance(cell) + 1);
    m_cellCount = qMax(m_cellCount, int(cells.size()));
    if (m_cellWidth != before || m_cellCount != beforeCount)
        updateGeometry();
}

void ReadoutPanel::showValues(const QString &time, const QStringList &cells) {
    m_hovering = true;
    m_time = time;
    m_cells = cells;
    learnWidths(cells);
    setAccessibleDescription(text());
    update();
}

void ReadoutPanel::showHint(const QStringList &lines) {
    m_hovering = false;
    m_hint = lines;
    setAccessibleDescription(text());
    setToolTip(lines.join(QLatin1Char('\n')));
    updateGeometry();
    update();
}

QString ReadoutPanel::text() const {
    if (!m_hovering)
        return m_hint.join(QLatin1Char('\n'));
    return m_time + QStringLiteral("   ") + m_cells.join(model::kReadoutJoin);
}

int ReadoutPanel::timeWidth() const {
    return fontMetrics().horizontalAdvance(QStringLiteral("00:00:00.000")) + 1;
}

int ReadoutPanel::columnsFor(int width) const {
    if (m_cellWidth <= 0)
        return 1;
    // The instant, a gap, then columns each a cell and a gap wide (the last gap may hang over).
    return qMax(1, (width - timeWidth()) / (m_cellWidth + kGap));
}

int ReadoutPanel::cellRowsFor(int width) const {
    const int columns = columnsFor(width);
    return qMax(1, (m_cellCount + columns - 1) / columns);
}

int ReadoutPanel::heightForWidth(int width) const {
    // The hint wraps nothing: each of its lines is short, and cut with "…" where it must be.
    const int rows = qMax(cellRowsFor(width), int(qMax<qsizetype>(1, m_hint.size())));
    return rows * fontMetrics().lineSpacing();
}

QSize ReadoutPanel::sizeHint() const {
    const int width = timeWidth() + kGap + qMax(1, m_cellCount) * (m_cellWidth + kGap);
    return {width, heightForWidth(width)};
}

QSize ReadoutPanel::minimumSizeHint() const {
    return {0, heightForWidth(width() > 0 ? width() : sizeHint().width())};
}

void ReadoutPanel::changeEvent(QEvent *event) {
    QWidget::changeEvent(event);
    // Widths measured in the old font: measured again in the new one.
    if (event->type() == QEvent::FontChange)
        setTemplate(m_template);
}

void ReadoutPanel::paintEvent(QPaintEvent *) {
    QPainter painter(this);
    painter.setPen(palette().color(QPalette::WindowText));
    const int line = fontMetrics().lineSpacing();
    if (!m_hovering) {
        for (int i = 0; i < m_hint.size(); ++i) {
            const QRect row(0, i * line, width(), line);
            painter.drawText(row, Qt::AlignLeft | Qt::AlignVCenter,
                             fontMetrics().elidedText(m_hint.at(i), Qt::ElideRight, width()));
        }
        return;
    }
    const int left = timeWidth() + kGap;
    painter.drawText(QRect(0, 0, timeWidth(), line), Qt::AlignLeft | Qt::AlignVCenter, m_time);
    const int columns = columnsFor(width());
    for (int i = 0; i < m_cells.size(); ++i) {
        const QRect cell(left + (i % columns) * (m_cellWidth + kGap), (i / columns) * line,
                         m_cellWidth, line);
        painter.drawText(cell, Qt::AlignLeft | Qt::AlignVCenter, m_cells.at(i));
    }
}

} // namespace tipscope::gui
