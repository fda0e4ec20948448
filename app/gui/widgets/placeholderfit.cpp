#include "placeholderfit.h"

#include <QLineEdit>
#include <QStyle>

namespace tipscope::gui {

namespace {
// QLineEdit's own margin either side of its text, and its clear button's room (icon, padding).
constexpr int kTextMargins = 2 * 2 + 2;
constexpr int kClearButtonPadding = 6 + 4;
} // namespace

void fitPlaceholders(QLineEdit &edit, const QStringList &examples) {
    int text = 0;
    for (const QString &e : examples)
        text = qMax(text, edit.fontMetrics().horizontalAdvance(e));
    int width = text + kTextMargins +
                2 * edit.style()->pixelMetric(QStyle::PM_DefaultFrameWidth, nullptr, &edit);
    if (edit.isClearButtonEnabled())
        width += edit.style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, &edit) +
                 kClearButtonPadding;
    edit.setMinimumWidth(qMax(edit.minimumWidth(), width));
    if (edit.maximumWidth() < width)
        edit.setMaximumWidth(width);
}

} // namespace tipscope::gui
