// Internal: the journal's one writer, living on its own thread with its own connection (Qt SQL
// connections belong to the thread that made them).
//
// drain() takes everything queued, keeps it in a backlog and writes the backlog in transactions
// of at most maxBatch records; `committed` names what each transaction made durable. A failure
// of the environment (disk full, read-only, locked, damaged) rolls the transaction back, keeps
// the backlog, sets the state to Failed with the reason and tries again every retryIntervalMs;
// a record the schema refuses is counted lost with the reason and the others are written. Once
// writing works again, a "journal" event records how many records were lost and why. Pruning
// deletes records older than the retention in small transactions, so appends never wait long.
#pragma once

#include "journalshared.h"

#include <QObject>
#include <QSqlError>
#include <memory>
#include <optional>

class QSqlError;
class QTimer;

namespace tipscope::journal {

class JournalStatements;

class JournalWriter : public QObject {
    Q_OBJECT
public:
    JournalWriter(std::shared_ptr<JournalShared> shared, QString path, JournalOptions options);
    ~JournalWriter() override;

    // Each of these runs on the writer thread.
    void start();
    void drain();
    void setRetentionDays(int days);
    void pruneStep();
    // Writes what it can, counts the rest lost, closes the connection.
    void close();

Q_SIGNALS:
    void committed(const tipscope::journal::Committed &ids);
    void stateChanged(tipscope::journal::JournalState state);
    void recordsLost(qint64 total, const QString &reason);
    void pruned(qint64 joints, qint64 events);

private:
    bool openDatabase();
    void closeDatabase();
    void takeQueue();
    void writeBacklog();
    bool writeBatch(std::size_t count);
    bool writeRequest(const Request &request, Committed &ids, QSqlError *error);
    void rollBack();
    void syncRetention();
    void fail(const QString &text, JournalProblem problem);
    void fail(const QSqlError &error);
    void retry();
    // False when nothing changed.
    bool setState(JournalState state, const QString &errorText = QString(),
                  JournalProblem problem = JournalProblem::None);
    void countLost(qint64 count, const QString &reason);
    void reportLosses();
    void pruneBatch();
    void finishPruning();

    std::shared_ptr<JournalShared> m_shared;
    QString m_path;
    JournalOptions m_options;
    QString m_connection;
    std::unique_ptr<JournalStatements> m_statements; // set while the connection is open
    std::deque<Request> m_backlog;
    QTimer *m_retryTimer = nullptr;
    QTimer *m_pruneTimer = nullptr;
    quint64 m_taken = 0; // requests taken from the queue so far
    qint64 m_lostReported = 0;
    bool m_pruneQueued = false;
    std::optional<int> m_retentionToStore; // set but not yet in the file

    qint64 m_prunedJoints = 0;
    qint64 m_prunedEvents = 0;
};

} // namespace tipscope::journal
