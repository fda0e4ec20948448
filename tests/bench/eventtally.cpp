#include "eventtally.h"

#include <QCoreApplication>

namespace tipscope::bench {

EventTally::EventTally() {
    QCoreApplication::instance()->installEventFilter(this);
}

EventTally::~EventTally() {
    if (QCoreApplication::instance())
        QCoreApplication::instance()->removeEventFilter(this);
}

bool EventTally::eventFilter(QObject *watched, QEvent *event) {
    if (size_t(event->type()) < m_counts.size())
        ++m_counts[size_t(event->type())];
    ++m_total;
    return QObject::eventFilter(watched, event);
}

} // namespace tipscope::bench
