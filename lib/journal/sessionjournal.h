// SessionJournal: keeps what one session sees in a journal, for every front end alike (the line
// service holds one per line: lib/service/lineservice.h): each joint the session's watcher ends,
// and each entry of its event log (station, port and feeder errors, alarms, status and tool
// changes, writes with their read-back, communication errors, connects and disconnects, joint
// warnings and tip wear).
//
// A flood the event log collapses into one entry is journaled once, as the log shows it. The
// journal may be shared by several sessions (one per line of a workspace). A line with a work
// context of its own has its records stamped with it; the others carry the journal's. Neither
// object owns the other; both must outlive this one.
#pragma once

#include "journal.h"

#include "model/session.h"

#include <QObject>
#include <optional>

namespace tipscope::journal {

class SessionJournal : public QObject {
    Q_OBJECT
public:
    // `lineContext`: the line's own work context; none: the journal's in force.
    SessionJournal(model::Session &session, Journal &journal,
                   std::optional<model::WorkContext> lineContext = std::nullopt,
                   QObject *parent = nullptr);

private:
    void keepJoint(const model::JointRecord &joint);
    void keepEvent(const model::Event &event);

    Journal &m_journal;
    std::optional<model::WorkContext> m_lineContext;
};

} // namespace tipscope::journal
