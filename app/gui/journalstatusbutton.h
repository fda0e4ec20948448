// JournalStatusButton: the status bar's word on the journal. It shows the work context stamped on
// every joint and event ("WO-1234 · SN-0042 · ana", or "No work order"); a click opens the
// dialog that changes it. When the journal cannot write, it says so in the error colour with the
// reason in the tooltip, and how many records wait or were lost; polling goes on regardless.
#pragma once

#include "journal/journal.h"
#include "journal/workcontextfile.h"

#include <QToolButton>

namespace tipscope::gui {

class JournalStatusButton : public QToolButton {
    Q_OBJECT
public:
    JournalStatusButton(journal::Journal &journal, journal::WorkContextFollower &context,
                        QWidget *parent = nullptr);
    void refresh();

private:
    journal::Journal &m_journal;
    journal::WorkContextFollower &m_context;
    QString m_contextProblem;
};

[[nodiscard]] QString workContextText(const model::WorkContext &context);

} // namespace tipscope::gui
