// Journal: the one place every front end (GUI, CLI, the headless agent) writes joints and
// events to, for traceability a plant can audit. A SQLite file through Qt SQL, in WAL mode.
//
// Contract:
// - append() never waits for the disk: it stamps the record with a new unique id and the work
//   context in force, queues it and returns the id. One writer thread writes the queue in
//   batched transactions; `committed` then names (row id and unique id) what is durable, on the
//   disk with a full sync. A record whose id was not in `committed` may be lost by a crash.
// - When the file cannot be written (read-only folder, full disk or size limit, damaged file,
//   newer schema) state() is Failed and errorText() says why in the user's language. Records
//   then wait in memory and the writer tries again every few seconds. Once queued and waiting
//   records reach backlogLimit, further appends are counted lost with the reason (lostCount(),
//   lossReason(), `recordsLost`) instead of kept; nothing is dropped silently, and after a
//   recovery a "journal" event in the journal itself says how many records were lost and why.
// - setContext() stamps every later joint and event and records a context-change event; a
//   record appended with a context of its own (a workspace line's) carries that one instead.
// - Store-and-forward marks records sent by row id (markJointsSent(), markEventsSent());
//   JournalReader lists the unsent ones in order.
// - Records older than the retention (default 365 days; 0 keeps all) are pruned on the writer
//   thread in small transactions: at opening, hourly, and when the retention changes. The
//   retention is kept in the file (journalsettings.h): setRetentionDays() stores it for every
//   program that opens the journal, and each reads it again before it prunes.
// - Appending, context and marks are thread-safe; the signals arrive on this object's thread.
//   Queries go through JournalReader, which has its own connection.
#pragma once

#include "base/outcome.h"
#include "journalstate.h"
#include "journaltypes.h"

#include <QObject>
#include <QThread>
#include <memory>

namespace tipscope::journal {

struct JournalShared;
class JournalWriter;

class Journal : public QObject {
    Q_OBJECT
public:
    // Changes of context remembered for the joints open across them, and how long before a
    // change a joint may have begun: a live joint ends within JointDetector::kGiveUpMs (30 s)
    // and its tail, and is appended at once.
    static constexpr int kContextsKept = 16;
    static constexpr qint64 kJointSpanMs = 60'000;

    // Opens (creates, migrates) `path`, or defaultPath() when empty, on the writer thread.
    explicit Journal(const QString &path = QString(), const JournalOptions &options = {},
                     QObject *parent = nullptr);
    ~Journal() override;

    // journal.sqlite in TipScope's application data folder (~/.local/share/TipScope/TipScope),
    // the same for every TipScope program whatever its own name.
    [[nodiscard]] static QString defaultPath();
    [[nodiscard]] QString path() const { return m_path; }

    // The record's unique id; a null id when the record was counted lost at once. A joint is
    // stamped with the work context in force when it began, not when it ended: one that spans
    // a change of board was soldered on the board named before (kContextsKept changes back).
    QUuid append(const model::JointRecord &joint);
    // An event without a time (0) is stamped with the wall clock.
    QUuid append(JournalEvent event);
    // The same, stamped with `context` instead of the journal's: a workspace line that has a work
    // context of its own.
    QUuid append(const model::JointRecord &joint, const model::WorkContext &context);
    QUuid append(JournalEvent event, const model::WorkContext &context);
    void markJointsSent(const QList<qint64> &ids);
    void markEventsSent(const QList<qint64> &ids, SentChannel channel = SentChannel::Mqtt);

    void setContext(const model::WorkContext &context);
    [[nodiscard]] model::WorkContext context() const;
    // The retention in force; the file's own once the journal has opened.
    [[nodiscard]] int retentionDays() const;
    // Refuses an impossible value at once; stores a possible one (when the file cannot be
    // written, as soon as it can) and prunes to it.
    base::Outcome<void> setRetentionDays(int days);

    [[nodiscard]] JournalState state() const;
    [[nodiscard]] QString errorText() const;
    // The kind of errorText(): None unless state() is Failed.
    [[nodiscard]] JournalProblem problem() const;
    [[nodiscard]] qint64 lostCount() const;
    [[nodiscard]] QString lossReason() const;
    // Records queued or held in memory, not yet written.
    [[nodiscard]] qint64 pendingCount() const;
    // A mark of everything appended so far, and whether all of it has since been dealt with
    // (written, held or counted lost): what a reader of the file can wait for without blocking.
    [[nodiscard]] quint64 appendedMark() const;
    [[nodiscard]] bool dealtWith(quint64 mark) const;

    // Waits until everything appended before the call is dealt with; true when all of it was
    // written. For shutdown, the CLI and tests: it blocks, so never call it on the poll path.
    [[nodiscard]] bool flush(int timeoutMs = 30000);
    // Writes what it can within `timeoutMs`, counts the rest lost, stops the writer. Later
    // appends are counted lost.
    void close(int timeoutMs = 10000);

Q_SIGNALS:
    void committed(const tipscope::journal::Committed &ids);
    void stateChanged(tipscope::journal::JournalState state);
    void recordsLost(qint64 total, const QString &reason);
    void pruned(qint64 joints, qint64 events);

private:
    // Stamped with `context`, or the journal's when null.
    template <typename Pending>
    QUuid enqueue(Pending pending, const model::WorkContext *context = nullptr);
    QUuid countLostNow(const QString &reason);

    QString m_path;
    std::shared_ptr<JournalShared> m_shared;
    QThread m_thread;
    JournalWriter *m_writer = nullptr; // lives on m_thread, deleted when it finishes
    int m_backlogLimit = 0;
};

} // namespace tipscope::journal
