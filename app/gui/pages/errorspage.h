// ErrorsPage: what is wrong now and what went wrong before, for support staff and technicians:
// the current state of every device and port above (ErrorStatePanel) and the event history
// below (EventHistoryPanel). Opening the page asks for the status values at once.
#pragma once

#include "page.h"

#include "base/outcome.h"

namespace tipscope::gui {

class ErrorStatePanel;
class EventHistoryPanel;

class ErrorsPage : public Page {
    Q_OBJECT
public:
    explicit ErrorsPage(model::Session &session, QWidget *parent = nullptr);

    [[nodiscard]] QString title() const override { return tr("Errors"); }
    void setActive(bool active) override;

    // Clears the error code of the session's feeder, as the Reset button does.
    void resetFeederError();
    // Copies the selected history rows to the clipboard, tab-separated, one event a line.
    void copySelection() const;
    // Writes the history rows that pass the filters, with a header line, tab-separated, UTF-8;
    // fails, saying why, when the file cannot be written.
    [[nodiscard]] base::Outcome<void> exportText(const QString &path) const;

private:
    ErrorStatePanel *m_state;
    EventHistoryPanel *m_history;
};

} // namespace tipscope::gui
