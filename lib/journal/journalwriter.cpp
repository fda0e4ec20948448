#include "journalwriter.h"

#include "journalschema.h"
#include "journalsettings.h"
#include "journalstatements.h"
#include "sqlerror.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLoggingCategory>
#include <QSqlDatabase>
#include <QTimer>
#include <algorithm>

namespace tipscope::journal {

Q_LOGGING_CATEGORY(lcJournal, "tipscope.journal")

namespace {

struct JournalWriterTr {
    Q_DECLARE_TR_FUNCTIONS(Journal)
};

// Records a request stands for (a batch of sent marks is not a record).
qint64 recordCount(const std::deque<Request> &requests) {
    return std::count_if(requests.begin(), requests.end(),
                         [](const Request &r) { return !std::holds_alternative<SentMarks>(r); });
}

} // namespace

JournalWriter::JournalWriter(std::shared_ptr<JournalShared> shared, QString path,
                             JournalOptions options)
    : m_shared(std::move(shared))
    , m_path(std::move(path))
    , m_options(options)
    , m_connection(QStringLiteral("tipscope.journal.writer.%1").arg(quintptr(this), 0, 16)) {}

JournalWriter::~JournalWriter() {
    closeDatabase();
}

void JournalWriter::start() {
    m_retryTimer = new QTimer(this);
    m_retryTimer->setSingleShot(true);
    m_retryTimer->setInterval(m_options.retryIntervalMs);
    connect(m_retryTimer, &QTimer::timeout, this, &JournalWriter::retry);
    m_pruneTimer = new QTimer(this);
    m_pruneTimer->setInterval(m_options.pruneIntervalMs);
    connect(m_pruneTimer, &QTimer::timeout, this, &JournalWriter::pruneStep);
    m_pruneTimer->start();
    if (openDatabase())
        setState(JournalState::Ready);
    takeQueue();
    writeBacklog();
    pruneStep();
}

bool JournalWriter::openDatabase() {
    JournalProblem problem = JournalProblem::None;
    if (const auto opened =
            openJournalDatabase(m_path, m_connection, m_options.maxSizeBytes, &problem);
        !opened) {
        fail(opened.error(), problem);
        return false;
    }
    m_statements = std::make_unique<JournalStatements>(QSqlDatabase::database(m_connection));
    QSqlError prepareError;
    if (!m_statements->prepare(&prepareError)) {
        closeDatabase();
        fail(prepareError);
        return false;
    }
    syncRetention();
    return true;
}

// Stores a retention set while the file could not take it, or reads the one the file holds
// (another program may have changed it), unless this program was given its own.
void JournalWriter::syncRetention() {
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    if (m_retentionToStore) {
        if (const auto stored = storeRetentionDays(db, *m_retentionToStore); !stored) {
            qCWarning(lcJournal).noquote() << stored.error();
            return;
        }
        m_retentionToStore.reset();
        return;
    }
    if (m_options.retentionDays)
        return;
    const auto days = readRetentionDays(db);
    if (!days) {
        qCWarning(lcJournal).noquote() << days.error();
        return;
    }
    QMutexLocker lock(&m_shared->mutex);
    m_shared->retentionDays = *days;
}

void JournalWriter::closeDatabase() {
    if (!QSqlDatabase::contains(m_connection))
        return;
    m_statements.reset();
    QSqlDatabase::database(m_connection, false).close();
    QSqlDatabase::removeDatabase(m_connection);
}

void JournalWriter::drain() {
    takeQueue();
    writeBacklog();
}

// Moves the queue into the backlog. writeBacklog() then says how many requests were dealt with
// (written, held or lost): flush() waits on that count.
void JournalWriter::takeQueue() {
    QMutexLocker lock(&m_shared->mutex);
    m_shared->drainPosted = false;
    m_taken += m_shared->queue.size();
    std::move(m_shared->queue.begin(), m_shared->queue.end(), std::back_inserter(m_backlog));
    m_shared->queue.clear();
    // Counted as held at once: the backlog limit must see these while a write of them is tried.
    m_shared->held = qint64(m_backlog.size());
}

void JournalWriter::writeBacklog() {
    if (m_statements) {
        while (!m_backlog.empty() &&
               writeBatch(qMin(m_backlog.size(), std::size_t(qMax(1, m_options.maxBatch)))))
            ;
        if (m_backlog.empty()) {
            setState(JournalState::Ready);
            reportLosses();
        }
    }
    QMutexLocker lock(&m_shared->mutex);
    m_shared->handled = m_taken;
    m_shared->held = qint64(m_backlog.size());
    m_shared->settled.wakeAll();
}

bool JournalWriter::writeBatch(std::size_t count) {
    QSqlError error;
    if (!m_statements->exec(QStringLiteral("BEGIN IMMEDIATE"), &error)) {
        fail(error);
        return false;
    }
    Committed ids;
    QStringList refused;
    for (std::size_t i = 0; i < count; ++i) {
        if (writeRequest(m_backlog[i], ids, &error))
            continue;
        if (!isRecordError(error)) {
            rollBack();
            fail(error);
            return false;
        }
        refused.append(describeSqlError(error, m_path));
    }
    if (!m_statements->exec(QStringLiteral("COMMIT"), &error)) {
        rollBack();
        fail(error);
        return false;
    }
    m_backlog.erase(m_backlog.begin(), m_backlog.begin() + qsizetype(count));
    if (!refused.isEmpty())
        countLost(refused.size(), refused.constLast());
    if (!ids.joints.isEmpty() || !ids.events.isEmpty())
        Q_EMIT committed(ids);
    return true;
}

bool JournalWriter::writeRequest(const Request &request, Committed &ids, QSqlError *error) {
    if (const auto *joint = std::get_if<PendingJoint>(&request)) {
        const std::optional<qint64> id = m_statements->insert(*joint, error);
        if (id)
            ids.joints.append({*id, joint->uid});
        return id.has_value();
    }
    if (const auto *event = std::get_if<PendingEvent>(&request)) {
        const std::optional<qint64> id = m_statements->insert(*event, error);
        if (id)
            ids.events.append({*id, event->uid});
        return id.has_value();
    }
    return m_statements->markSent(std::get<SentMarks>(request), error);
}

void JournalWriter::rollBack() {
    QSqlError ignored; // SQLite may have rolled back already (a full disk does)
    (void)m_statements->exec(QStringLiteral("ROLLBACK"), &ignored);
    m_statements->forgetIds();
}

void JournalWriter::fail(const QSqlError &error) {
    fail(describeSqlError(error, m_path), problemOf(error, m_path));
}

void JournalWriter::fail(const QString &text, JournalProblem problem) {
    if (setState(JournalState::Failed, text, problem))
        qCWarning(lcJournal).noquote() << text;
    if (m_retryTimer && !m_retryTimer->isActive())
        m_retryTimer->start();
}

void JournalWriter::retry() {
    if (!m_statements && !openDatabase())
        return;
    takeQueue();
    writeBacklog();
}

bool JournalWriter::setState(JournalState state, const QString &errorText, JournalProblem problem) {
    {
        QMutexLocker lock(&m_shared->mutex);
        if (m_shared->state == state && m_shared->errorText == errorText)
            return false;
        m_shared->state = state;
        m_shared->errorText = errorText;
        m_shared->problem = problem;
    }
    Q_EMIT stateChanged(state);
    return true;
}

void JournalWriter::countLost(qint64 count, const QString &reason) {
    qint64 total = 0;
    {
        QMutexLocker lock(&m_shared->mutex);
        m_shared->lost += count;
        m_shared->lossReason = reason;
        total = m_shared->lost;
    }
    qCWarning(lcJournal).noquote() << count << "records lost:" << reason;
    Q_EMIT recordsLost(total, reason);
}

// Once the journal writes again, it says in itself how many records it lost and why.
void JournalWriter::reportLosses() {
    PendingEvent report;
    {
        QMutexLocker lock(&m_shared->mutex);
        if (m_shared->lost <= m_lostReported)
            return;
        const qint64 lost = m_shared->lost - m_lostReported;
        m_lostReported = m_shared->lost;
        report.context = m_shared->context;
        report.event.details = {{QStringLiteral("lost"), lost},
                                {QStringLiteral("reason"), m_shared->lossReason}};
        report.event.text =
            JournalWriterTr::tr("Records lost: %1. Reason: %2").arg(lost).arg(m_shared->lossReason);
    }
    report.uid = QUuid::createUuid();
    report.event.kind = JournalEvent::Kind::Journal;
    report.event.severity = JournalEvent::Severity::Error;
    report.event.timeMs = QDateTime::currentMSecsSinceEpoch();
    m_backlog.push_back(std::move(report));
    writeBatch(m_backlog.size());
}

// In force again here, not only in Journal::setRetentionDays(): the read at opening may have
// come between the two. Then into the file.
void JournalWriter::setRetentionDays(int days) {
    {
        QMutexLocker lock(&m_shared->mutex);
        m_shared->retentionDays = days;
    }
    m_options.retentionDays.reset(); // the file holds the chosen one from now on
    m_retentionToStore = days;
    pruneStep();
}

void JournalWriter::pruneStep() {
    if (m_statements)
        syncRetention();
    if (!m_pruneQueued)
        pruneBatch();
}

void JournalWriter::pruneBatch() {
    int days = 0;
    {
        QMutexLocker lock(&m_shared->mutex);
        days = m_shared->retentionDays;
    }
    if (!m_statements || days <= 0)
        return;
    const qint64 cutoff = QDateTime::currentMSecsSinceEpoch() - days * kDayMs;
    const int limit = qMax(1, m_options.pruneBatch);
    QSqlError error;
    std::optional<int> joints;
    std::optional<int> events;
    const bool done = m_statements->exec(QStringLiteral("BEGIN IMMEDIATE"), &error) &&
                      (joints = m_statements->prune(Table::Joints, cutoff, limit, &error)) &&
                      (events = m_statements->prune(Table::Events, cutoff, limit, &error)) &&
                      m_statements->exec(QStringLiteral("COMMIT"), &error);
    if (!done) {
        rollBack();
        fail(error);
        return;
    }
    m_prunedJoints += *joints;
    m_prunedEvents += *events;
    // More to go: the next step waits behind whatever was queued meanwhile.
    if (*joints < limit && *events < limit) {
        finishPruning();
        return;
    }
    m_pruneQueued = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_pruneQueued = false;
            pruneBatch();
        },
        Qt::QueuedConnection);
}

void JournalWriter::finishPruning() {
    if (m_prunedJoints + m_prunedEvents == 0)
        return;
    Q_EMIT pruned(m_prunedJoints, m_prunedEvents);
    m_prunedJoints = 0;
    m_prunedEvents = 0;
    // Space the pruning freed may be what a full journal was waiting for.
    if (!m_backlog.empty())
        writeBacklog();
}

void JournalWriter::close() {
    takeQueue();
    writeBacklog();
    const qint64 left = recordCount(m_backlog);
    if (left > 0) {
        QString reason;
        {
            QMutexLocker lock(&m_shared->mutex);
            reason = m_shared->errorText;
        }
        countLost(left, JournalWriterTr::tr("The journal was closed before it could write them: %1")
                            .arg(reason));
    }
    m_backlog.clear();
    if (m_retryTimer)
        m_retryTimer->stop();
    if (m_pruneTimer)
        m_pruneTimer->stop();
    closeDatabase();
    setState(JournalState::Closed);
    QMutexLocker lock(&m_shared->mutex);
    m_shared->handled = m_taken;
    m_shared->held = 0;
    m_shared->settled.wakeAll();
}

} // namespace tipscope::journal
