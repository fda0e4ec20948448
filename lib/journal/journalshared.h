// Internal: what a Journal and its writer thread share. Everything here is guarded by `mutex`;
// the writer signals `settled` whenever it has dealt with more requests, which flush() waits on.
#pragma once

#include "journalsettings.h"
#include "journalstate.h"
#include "journaltypes.h"

#include <QMutex>
#include <QWaitCondition>
#include <deque>
#include <variant>

namespace tipscope::journal {

struct PendingJoint {
    QUuid uid;
    model::WorkContext context;
    model::JointRecord joint;
};

struct PendingEvent {
    QUuid uid;
    model::WorkContext context;
    JournalEvent event;
};

enum class Table { Joints, Events };

struct SentMarks {
    Table table = Table::Joints;
    QList<qint64> ids;
    SentChannel channel = SentChannel::Mqtt;
};

using Request = std::variant<PendingJoint, PendingEvent, SentMarks>;

struct JournalShared {
    QMutex mutex;
    QWaitCondition settled;
    std::deque<Request> queue;
    bool drainPosted = false;
    quint64 appended = 0; // requests queued so far
    quint64 handled = 0;  // requests the writer has written, held or counted lost
    qint64 held = 0;      // records the writer keeps in memory because it cannot write
    qint64 lost = 0;
    QString lossReason;
    JournalState state = JournalState::Opening;
    QString errorText;
    JournalProblem problem = JournalProblem::None;
    model::WorkContext context;
    // The contexts before `context`, newest last, each with the time it ended, for the joints
    // still open at a change (Journal::append of a joint); at most kContextsKept.
    std::deque<std::pair<qint64, model::WorkContext>> earlierContexts;
    int retentionDays = kDefaultRetentionDays; // in force
};

} // namespace tipscope::journal
