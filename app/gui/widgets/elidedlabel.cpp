#include "elidedlabel.h"

#include <QResizeEvent>

namespace tipscope::gui {

ElidedLabel::ElidedLabel(QWidget *parent)
    : QLabel(parent) {
    setTextFormat(Qt::PlainText);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

void ElidedLabel::setFullText(const QString &text) {
    m_full = text;
    setAccessibleDescription(text);
    elide();
    updateGeometry();
}

QSize ElidedLabel::minimumSizeHint() const {
    // Room for "…" and a few letters: enough to see that there is more to read.
    const QFontMetrics fm = fontMetrics();
    const int width =
        qMin(fm.horizontalAdvance(m_full), fm.horizontalAdvance(QStringLiteral("Wwww…")));
    return {width + 2 * margin(), QLabel::minimumSizeHint().height()};
}

QSize ElidedLabel::sizeHint() const {
    // A pixel more than the advance: glyph overhang and rounding would otherwise elide a text that
    // just fits.
    return {fontMetrics().horizontalAdvance(m_full) + 2 * margin() + 2,
            QLabel::sizeHint().height()};
}

void ElidedLabel::resizeEvent(QResizeEvent *event) {
    QLabel::resizeEvent(event);
    elide();
}

void ElidedLabel::elide() {
    const int room = contentsRect().width() - 2 * margin();
    const QString shown = fontMetrics().elidedText(m_full, Qt::ElideMiddle, qMax(0, room));
    setText(shown);
    setToolTip(shown != m_full ? m_full : QString());
}

} // namespace tipscope::gui
