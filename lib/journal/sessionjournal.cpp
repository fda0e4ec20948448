#include "sessionjournal.h"

namespace tipscope::journal {

SessionJournal::SessionJournal(model::Session &session, Journal &journal, QObject *parent)
    : QObject(parent)
    , m_journal(journal) {
    connect(&session.joints(), &model::JointWatcher::jointEnded, this,
            [this](const model::JointRecord &joint) { m_journal.append(joint); });
    connect(&session.eventLog(), &model::EventLog::appended, this, &SessionJournal::keepEvent);
}

void SessionJournal::keepEvent(const model::Event &event) {
    const std::optional<int> port = event.port > 0 ? std::optional<int>(event.port) : std::nullopt;
    m_journal.append(JournalEvent::fromEventLog(event, event.device, port));
}

} // namespace tipscope::journal
