#include "elidedlabel.h"

#include <QResizeEvent>
#include <QtMath>

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
    // Room for "…" and two characters of the label's font: enough to see that there is more to
    // read, in whatever font and size the label is shown.
    const QFontMetrics fm = fontMetrics();
    const int least = fm.horizontalAdvance(QChar(0x2026)) + 2 * fm.averageCharWidth();
    return {qMin(textWidth(), least) + 2 * margin(), QLabel::minimumSizeHint().height()};
}

QSize ElidedLabel::sizeHint() const {
    return {textWidth() + 2 * margin(), QLabel::sizeHint().height()};
}

int ElidedLabel::textWidth() const {
    // The exact advance rounded up: QFontMetrics rounds to the nearest pixel, and a text given a
    // width below its exact advance would be elided although it was asked to fit.
    return qCeil(QFontMetricsF(font()).horizontalAdvance(m_full));
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
