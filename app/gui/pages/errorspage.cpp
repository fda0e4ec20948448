#include "errorspage.h"

#include "errorstatepanel.h"
#include "eventhistorypanel.h"

#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;

ErrorsPage::ErrorsPage(Session &session, QWidget *parent)
    : Page(session, parent)
    , m_state(new ErrorStatePanel(session, this))
    , m_history(new EventHistoryPanel(session, this)) {
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_state);
    layout->addWidget(m_history, 1);
}

void ErrorsPage::setActive(bool active) {
    Page::setActive(active);
    // Errors are polled every few seconds; someone opening the page wants them now.
    if (active)
        for (DeviceModel *device : m_session.devices())
            m_session.scheduler().requestRefresh(device, PollClass::Status);
}

void ErrorsPage::resetFeederError() {
    m_state->resetFeederError();
}

void ErrorsPage::copySelection() const {
    m_history->copySelection();
}

base::Outcome<void> ErrorsPage::exportText(const QString &path) const {
    return m_history->exportText(path);
}

} // namespace tipscope::gui
