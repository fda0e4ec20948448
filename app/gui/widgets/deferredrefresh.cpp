#include "deferredrefresh.h"

#include <QEvent>

namespace tipscope::gui {

DeferredRefresh::DeferredRefresh(QWidget &widget, std::function<void()> refresh)
    : QObject(&widget)
    , m_widget(&widget)
    , m_refresh(std::move(refresh)) {
    widget.installEventFilter(this);
}

void DeferredRefresh::request() {
    if (m_widget && m_widget->window()->isVisible() && !m_widget->isVisible()) {
        m_due = true;
        return;
    }
    m_due = false;
    m_refresh();
}

void DeferredRefresh::flush() {
    if (m_due) {
        m_due = false;
        m_refresh();
    }
}

bool DeferredRefresh::eventFilter(QObject *watched, QEvent *event) {
    if (watched == m_widget && event->type() == QEvent::Show)
        flush();
    return QObject::eventFilter(watched, event);
}

} // namespace tipscope::gui
