#include "flowlayout.h"

#include <QStyle>
#include <QWidget>

namespace tipscope::gui {

FlowLayout::FlowLayout(QWidget *parent)
    : QLayout(parent) {}

FlowLayout::~FlowLayout() {
    while (QLayoutItem *item = takeAt(0))
        delete item;
}

void FlowLayout::addItem(QLayoutItem *item) {
    m_items.append(item);
}

QLayoutItem *FlowLayout::itemAt(int index) const {
    return index >= 0 && index < m_items.size() ? m_items.at(index) : nullptr;
}

QLayoutItem *FlowLayout::takeAt(int index) {
    return index >= 0 && index < m_items.size() ? m_items.takeAt(index) : nullptr;
}

int FlowLayout::heightForWidth(int width) const {
    return arrange(QRect(0, 0, width, 0), false);
}

QSize FlowLayout::minimumSize() const {
    // As narrow as the widest single item: everything else can go onto another line.
    QSize size;
    for (const QLayoutItem *item : m_items)
        size = size.expandedTo(item->minimumSize());
    const QMargins m = contentsMargins();
    return size + QSize(m.left() + m.right(), m.top() + m.bottom());
}

QSize FlowLayout::sizeHint() const {
    // One line, every item at its preferred size.
    int width = 0, height = 0;
    for (const QLayoutItem *item : m_items) {
        if (item->isEmpty())
            continue;
        width += (width > 0 ? gap(Qt::Horizontal) : 0) + item->sizeHint().width();
        height = qMax(height, item->sizeHint().height());
    }
    const QMargins m = contentsMargins();
    return {width + m.left() + m.right(), height + m.top() + m.bottom()};
}

void FlowLayout::setGeometry(const QRect &rect) {
    QLayout::setGeometry(rect);
    arrange(rect, true);
}

int FlowLayout::arrange(const QRect &rect, bool place) const {
    const QRect area = rect.marginsRemoved(contentsMargins());
    int x = area.x(), y = area.y(), lineHeight = 0;
    // Each line is placed once it is known, so that its items share its height.
    QList<QPair<QLayoutItem *, QPoint>> line;
    const auto finishLine = [&] {
        if (place)
            for (const auto &[item, at] : std::as_const(line)) {
                const QSize size = item->sizeHint();
                // Centred on the line, unless the item asks for its top (tiles of a wall).
                const int dy =
                    item->alignment() & Qt::AlignTop ? 0 : (lineHeight - size.height()) / 2;
                item->setGeometry(
                    QRect(QPoint(at.x(), at.y() + dy),
                          size.boundedTo(QSize(area.right() - at.x() + 1, lineHeight))));
            }
        line.clear();
    };
    for (QLayoutItem *item : m_items) {
        if (item->isEmpty())
            continue;
        const QSize size = item->sizeHint();
        if (!line.isEmpty() && x + size.width() > area.right() + 1) {
            finishLine();
            x = area.x();
            y += lineHeight + gap(Qt::Vertical);
            lineHeight = 0;
        }
        line.append({item, QPoint(x, y)});
        x += size.width() + gap(Qt::Horizontal);
        lineHeight = qMax(lineHeight, size.height());
    }
    finishLine();
    return y + lineHeight - rect.y() + contentsMargins().bottom();
}

int FlowLayout::gap(Qt::Orientation orientation) const {
    if (spacing() >= 0)
        return spacing();
    const QWidget *owner = parentWidget();
    if (!owner)
        return 6;
    const int metric = owner->style()->pixelMetric(orientation == Qt::Horizontal
                                                       ? QStyle::PM_LayoutHorizontalSpacing
                                                       : QStyle::PM_LayoutVerticalSpacing,
                                                   nullptr, owner);
    return metric >= 0 ? metric : 6; // styles that space by control type answer -1
}

} // namespace tipscope::gui
