// SessionJournal: keeps what one session sees in a journal, for every front end alike (the GUI,
// the CLI's monitor, the line service): each joint the session's watcher ends, and each entry of
// its event log (station, port and feeder errors, alarms, status and tool changes, writes with
// their read-back, communication errors, connects and disconnects, joint warnings and tip wear).
//
// A flood the event log collapses into one entry is journaled once, as the log shows it. The
// journal may be shared by several sessions (one per line of a workspace). Neither object owns
// the other; both must outlive this one.
#pragma once

#include "journal.h"

#include "model/session.h"

#include <QObject>

namespace tipscope::journal {

class SessionJournal : public QObject {
    Q_OBJECT
public:
    SessionJournal(model::Session &session, Journal &journal, QObject *parent = nullptr);

private:
    void keepEvent(const model::Event &event);

    Journal &m_journal;
};

} // namespace tipscope::journal
