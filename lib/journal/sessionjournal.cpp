#include "sessionjournal.h"

namespace tipscope::journal {

SessionJournal::SessionJournal(model::Session &session, Journal &journal,
                               std::optional<model::WorkContext> lineContext, QObject *parent)
    : QObject(parent)
    , m_journal(journal)
    , m_lineContext(std::move(lineContext)) {
    connect(&session.joints(), &model::JointWatcher::jointEnded, this, &SessionJournal::keepJoint);
    connect(&session.eventLog(), &model::EventLog::appended, this, &SessionJournal::keepEvent);
}

void SessionJournal::keepJoint(const model::JointRecord &joint) {
    if (m_lineContext)
        m_journal.append(joint, *m_lineContext);
    else
        m_journal.append(joint);
}

void SessionJournal::keepEvent(const model::Event &event) {
    const std::optional<int> port = event.port > 0 ? std::optional<int>(event.port) : std::nullopt;
    JournalEvent record = JournalEvent::fromEventLog(event, event.device, port);
    if (m_lineContext)
        m_journal.append(std::move(record), *m_lineContext);
    else
        m_journal.append(std::move(record));
}

} // namespace tipscope::journal
