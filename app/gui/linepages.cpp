#include "linepages.h"

#include "pages/jointspage.h"
#include "pages/pagefactory.h"

namespace tipscope::gui {

using namespace tipscope::model;

LinePages::LinePages(Session &session, const QString &journalPath, PortsPolled polled,
                     QWidget *parent)
    : QTabWidget(parent)
    , m_session(session)
    , m_polled(polled) {
    setDocumentMode(true);
    m_pages = createPages(session, this);
    for (Page *p : std::as_const(m_pages)) {
        addTab(p, p->title());
        if (auto *joints = qobject_cast<JointsPage *>(p)) {
            joints->setJournalPath(journalPath);
            connect(joints, &JointsPage::chartsShown, this, &QTabWidget::setCurrentWidget);
        }
    }
    connect(this, &QTabWidget::currentChanged, this, &LinePages::onTabChanged);
    connect(&session, &Session::devicesChanged, this, &LinePages::updateVisiblePorts);
}

Page *LinePages::page(const QString &title) const {
    for (Page *p : m_pages)
        if (p->title() == title)
            return p;
    return nullptr;
}

void LinePages::select(DeviceModel *device, int port) {
    m_device = device;
    for (Page *p : std::as_const(m_pages)) {
        p->setSelection(device, port);
        setTabVisible(indexOf(p), !device || p->appliesTo(device));
    }
    updateVisiblePorts();
}

void LinePages::setShown(bool shown) {
    m_shown = shown;
    onTabChanged(currentIndex());
}

void LinePages::setWorkOrder(const QString &workOrder) {
    for (Page *p : std::as_const(m_pages))
        if (auto *joints = qobject_cast<JointsPage *>(p))
            joints->setWorkOrder(workOrder);
}

void LinePages::showPage(const QString &title) {
    Page *p = page(title);
    if (p && isTabVisible(indexOf(p)))
        setCurrentWidget(p);
}

void LinePages::onTabChanged(int index) {
    for (Page *p : std::as_const(m_pages))
        p->setActive(m_shown && indexOf(p) == index);
    updateVisiblePorts();
}

void LinePages::updateVisiblePorts() {
    if (m_polled == PortsPolled::Every)
        return;
    // The shown page decides which ports' live values are worth the wire.
    auto *current = qobject_cast<Page *>(currentWidget());
    const QSet<int> ports = m_shown && current ? current->visiblePorts() : QSet<int>();
    for (DeviceModel *d : m_session.devices())
        m_session.scheduler().setVisiblePorts(d, qobject_cast<StationModel *>(d) ? ports
                                                                                 : QSet<int>());
}

} // namespace tipscope::gui
