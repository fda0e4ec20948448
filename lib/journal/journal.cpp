#include "journal.h"

#include "journalshared.h"
#include "journalwriter.h"

#include "model/context/workcontextjson.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDeadlineTimer>
#include <QDir>
#include <QStandardPaths>

namespace tipscope::journal {

namespace {

// Queues a request for the writer; false once the journal is closed.
bool post(JournalShared &shared, JournalWriter *writer, Request request) {
    bool wake = false;
    {
        QMutexLocker lock(&shared.mutex);
        if (shared.state == JournalState::Closed)
            return false;
        shared.queue.push_back(std::move(request));
        ++shared.appended;
        wake = !shared.drainPosted;
        shared.drainPosted = true;
    }
    if (wake)
        QMetaObject::invokeMethod(writer, &JournalWriter::drain, Qt::QueuedConnection);
    return true;
}

// When a record began: a joint's start; an event's own time.
qint64 startOf(const PendingJoint &pending) {
    return pending.joint.startMs;
}
qint64 startOf(const PendingEvent &pending) {
    return pending.event.timeMs;
}

// The context in force at `timeMs`: an earlier one that ended after it, when that was within
// Journal::kJointSpanMs (a live joint's start); else the current one, as for a record stamped
// with another clock than the wall's (a recording played back). Called with the mutex held.
model::WorkContext contextAt(const JournalShared &shared, qint64 timeMs) {
    for (const auto &[endedMs, context] : shared.earlierContexts)
        if (timeMs < endedMs)
            return endedMs - timeMs <= Journal::kJointSpanMs ? context : shared.context;
    return shared.context;
}

} // namespace

Journal::Journal(const QString &path, const JournalOptions &options, QObject *parent)
    : QObject(parent)
    , m_path(path.isEmpty() ? defaultPath() : path)
    , m_shared(std::make_shared<JournalShared>())
    , m_backlogLimit(qMax(1, options.backlogLimit)) {
    qRegisterMetaType<Committed>();
    qRegisterMetaType<JournalState>();
    if (options.retentionDays)
        m_shared->retentionDays = *options.retentionDays;
    m_writer = new JournalWriter(m_shared, m_path, options);
    m_writer->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_writer, &QObject::deleteLater);
    connect(m_writer, &JournalWriter::committed, this, &Journal::committed);
    connect(m_writer, &JournalWriter::stateChanged, this, &Journal::stateChanged);
    connect(m_writer, &JournalWriter::recordsLost, this, &Journal::recordsLost);
    connect(m_writer, &JournalWriter::pruned, this, &Journal::pruned);
    m_thread.setObjectName(QStringLiteral("journal writer"));
    m_thread.start();
    QMetaObject::invokeMethod(m_writer, &JournalWriter::start, Qt::QueuedConnection);
}

Journal::~Journal() {
    close();
}

QString Journal::defaultPath() {
    const QString data = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    return QDir(data).filePath(QStringLiteral("TipScope/TipScope/journal.sqlite"));
}

QUuid Journal::append(const model::JointRecord &joint) {
    return enqueue(PendingJoint{QUuid(), {}, joint});
}

QUuid Journal::append(JournalEvent event) {
    if (event.timeMs == 0)
        event.timeMs = QDateTime::currentMSecsSinceEpoch();
    return enqueue(PendingEvent{QUuid(), {}, std::move(event)});
}

QUuid Journal::append(const model::JointRecord &joint, const model::WorkContext &context) {
    return enqueue(PendingJoint{QUuid(), {}, joint}, &context);
}

QUuid Journal::append(JournalEvent event, const model::WorkContext &context) {
    if (event.timeMs == 0)
        event.timeMs = QDateTime::currentMSecsSinceEpoch();
    return enqueue(PendingEvent{QUuid(), {}, std::move(event)}, &context);
}

template <typename Pending>
QUuid Journal::enqueue(Pending pending, const model::WorkContext *context) {
    QString reason;
    {
        QMutexLocker lock(&m_shared->mutex);
        if (m_shared->state == JournalState::Closed) {
            reason = tr("The journal is closed.");
        } else if (qint64(m_shared->queue.size()) + m_shared->held >= m_backlogLimit) {
            reason = m_shared->state == JournalState::Failed
                         ? m_shared->errorText
                         : tr("The journal cannot keep up: %1 records wait to be written.")
                               .arg(m_backlogLimit);
        }
        if (reason.isEmpty()) {
            pending.uid = QUuid::createUuid();
            pending.context = context ? *context : contextAt(*m_shared, startOf(pending));
            const QUuid uid = pending.uid;
            lock.unlock();
            return post(*m_shared, m_writer, std::move(pending))
                       ? uid
                       : countLostNow(tr("The journal is closed."));
        }
    }
    return countLostNow(reason);
}

QUuid Journal::countLostNow(const QString &reason) {
    qint64 total = 0;
    {
        QMutexLocker lock(&m_shared->mutex);
        total = ++m_shared->lost;
        m_shared->lossReason = reason;
    }
    Q_EMIT recordsLost(total, reason);
    return {};
}

void Journal::markJointsSent(const QList<qint64> &ids) {
    if (!ids.isEmpty())
        (void)post(*m_shared, m_writer, SentMarks{Table::Joints, ids});
}

void Journal::markEventsSent(const QList<qint64> &ids, SentChannel channel) {
    if (!ids.isEmpty())
        (void)post(*m_shared, m_writer, SentMarks{Table::Events, ids, channel});
}

void Journal::setContext(const model::WorkContext &context) {
    model::WorkContext before;
    const qint64 nowMs = QDateTime::currentMSecsSinceEpoch();
    {
        QMutexLocker lock(&m_shared->mutex);
        before = m_shared->context;
        if (before == context)
            return;
        m_shared->context = context;
        m_shared->earlierContexts.emplace_back(nowMs, before);
        if (m_shared->earlierContexts.size() > std::size_t(kContextsKept))
            m_shared->earlierContexts.pop_front();
    }
    JournalEvent event;
    event.timeMs = nowMs; // the moment the context changed, as the joints are told
    event.kind = JournalEvent::Kind::ContextChange;
    event.text = tr("Work order: %1, board: %2, operator: %3")
                     .arg(context.workOrder, context.boardSerial, context.operatorName);
    event.details = {{QStringLiteral("from"), model::workContextToJson(before)},
                     {QStringLiteral("to"), model::workContextToJson(context)}};
    append(std::move(event));
}

model::WorkContext Journal::context() const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->context;
}

int Journal::retentionDays() const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->retentionDays;
}

base::Outcome<void> Journal::setRetentionDays(int days) {
    if (const auto valid = checkRetentionDays(days); !valid)
        return valid;
    if (!m_thread.isRunning())
        return base::failure(tr("The journal is closed.")); // the writer is gone
    {
        QMutexLocker lock(&m_shared->mutex); // in force at once; the writer stores it
        m_shared->retentionDays = days;
    }
    QMetaObject::invokeMethod(
        m_writer, [writer = m_writer, days] { writer->setRetentionDays(days); },
        Qt::QueuedConnection);
    return {};
}

JournalState Journal::state() const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->state;
}

QString Journal::errorText() const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->errorText;
}

JournalProblem Journal::problem() const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->problem;
}

qint64 Journal::lostCount() const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->lost;
}

QString Journal::lossReason() const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->lossReason;
}

qint64 Journal::pendingCount() const {
    QMutexLocker lock(&m_shared->mutex);
    return qint64(m_shared->queue.size()) + m_shared->held;
}

quint64 Journal::appendedMark() const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->appended;
}

bool Journal::dealtWith(quint64 mark) const {
    QMutexLocker lock(&m_shared->mutex);
    return m_shared->handled >= mark;
}

bool Journal::flush(int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    QMutexLocker lock(&m_shared->mutex);
    const quint64 target = m_shared->appended;
    while (m_shared->handled < target) {
        if (!m_shared->settled.wait(&m_shared->mutex, deadline))
            return false;
    }
    return m_shared->held == 0 && m_shared->state != JournalState::Failed;
}

void Journal::close(int timeoutMs) {
    if (!m_thread.isRunning())
        return;
    (void)flush(timeoutMs);
    QMetaObject::invokeMethod(m_writer, &JournalWriter::close, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

} // namespace tipscope::journal
