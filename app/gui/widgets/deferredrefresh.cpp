#include "deferredrefresh.h"

#include <QEvent>

namespace tipscope::gui {

DeferredRefresh::DeferredRefresh(QWidget &widget, std::function<void()> refresh, QObject *owner)
    : DeferredRefresh(widget,
                      std::function<void(int)>([refresh = std::move(refresh)](int) { refresh(); }),
                      owner) {}

DeferredRefresh::DeferredRefresh(QWidget &widget, std::function<void(int)> refresh, QObject *owner)
    : QObject(owner ? owner : &widget)
    , m_widget(&widget)
    , m_refresh(std::move(refresh)) {
    widget.installEventFilter(this);
}

void DeferredRefresh::requestPart(int key) {
    if (m_widget && m_widget->window()->isVisible() && !m_widget->isVisible()) {
        if (!m_due.contains(key))
            m_due.append(key);
        return;
    }
    m_due.removeOne(key);
    m_refresh(key);
}

void DeferredRefresh::flush() {
    // A refresh may request again (or show the widget): take the list first.
    const QList<int> due = std::exchange(m_due, {});
    for (int key : due)
        m_refresh(key);
}

bool DeferredRefresh::eventFilter(QObject *watched, QEvent *event) {
    if (watched == m_widget && event->type() == QEvent::Show)
        flush();
    return QObject::eventFilter(watched, event);
}

} // namespace tipscope::gui
