// JournalReader: queries over a journal file, through a connection of its own. Synchronous: for
// the CLI, reports and pages that query off the poll path. A reader may run beside a Journal
// writing the same file (WAL lets readers see every committed transaction without blocking
// the writer). Use one reader on one thread: Qt SQL connections belong to their thread.
//
// open() refuses a missing file (it never creates one), a damaged or foreign file and a newer
// schema, and only reads a current one, so a journal on a read-only mount or another user's
// opens; an older schema is migrated as the writer would. check() is the one integrity check
// every command that reports on a journal runs. Every query that fails says why, in the user's
// language, and problem() says its kind.
#pragma once

#include "journalstate.h"
#include "journaltypes.h"

#include "base/outcome.h"

#include <QMap>
#include <QString>

namespace tipscope::journal {

class JournalReader {
public:
    JournalReader();
    ~JournalReader();
    JournalReader(const JournalReader &) = delete;
    JournalReader &operator=(const JournalReader &) = delete;

    [[nodiscard]] base::Outcome<void> open(const QString &path);
    // open() unless already open: for a forwarder that reads on, and opens again after failing.
    [[nodiscard]] base::Outcome<void> keepOpen(const QString &path);
    [[nodiscard]] bool isOpen() const { return m_open; }
    // SQLite's quick_check over the whole file: a journal that opens may still be damaged inside.
    // It reads every page, so it is for commands that report on the journal, not the poll path.
    [[nodiscard]] base::Outcome<void> check();
    // Why the last open() or check() failed, by kind; None after good ones.
    [[nodiscard]] JournalProblem problem() const { return m_problem; }
    [[nodiscard]] QString path() const { return m_path; }

    [[nodiscard]] base::Outcome<QList<StoredJoint>> joints(const JointFilter &filter) const;
    [[nodiscard]] base::Outcome<QList<StoredEvent>> events(const EventFilter &filter) const;
    // Ignores the filter's limit and order.
    [[nodiscard]] base::Outcome<qint64> countJoints(const JointFilter &filter) const;
    [[nodiscard]] base::Outcome<QMap<model::JointVerdict, qint64>>
    verdictCounts(const JointFilter &filter) const;
    // Per device and port, in key and port order.
    [[nodiscard]] base::Outcome<QList<PortRecovery>>
    recoveryByPort(const JointFilter &filter) const;

    // Store-and-forward: the oldest unsent records with a row id above `afterId`, in order.
    [[nodiscard]] base::Outcome<QList<StoredJoint>> unsentJoints(qint64 afterId, int limit) const;
    [[nodiscard]] base::Outcome<QList<StoredEvent>>
    unsentEvents(qint64 afterId, int limit, SentChannel channel = SentChannel::Mqtt) const;
    [[nodiscard]] base::Outcome<JournalSummary> summary() const;
    // The retention stored in the file (journalsettings.h), without counting anything.
    [[nodiscard]] base::Outcome<int> retentionDays() const;

    // Every device the journal has a record of, in key order.
    [[nodiscard]] base::Outcome<QList<model::DeviceIdentity>> devices() const;

private:
    void close();

    QString m_connection;
    QString m_path;
    bool m_open = false;
    JournalProblem m_problem = JournalProblem::None;
};

} // namespace tipscope::journal
