#include "cfxforwarder.h"

#include "amqpsender.h"
#include "cfxboard.h"
#include "cfxmessages.h"

#include "journal/journal.h"
#include "model/workcontextjson.h"

#include <QDateTime>
#include <QJsonArray>
#include <QLoggingCategory>
#include <QSet>
#include <algorithm>

Q_LOGGING_CATEGORY(lcCfxForwarder, "tipscope.cfx.forwarder")

namespace tipscope::cfx {

namespace {
constexpr int kBatch = 100;
constexpr int kMarkEveryMs = 200;
// How far back a clearing looks for the error it clears, after a restart forgot it.
constexpr int kLookBack = 50;
// How often a board waiting for its joints looks again.
constexpr int kBoardCheckMs = 100;

using Severity = journal::JournalEvent::Severity;

// The board serial a context change names; empty: none.
QString boardNamedBy(const journal::StoredEvent &change) {
    const auto to =
        model::workContextFromJson(change.record.details.value(QStringLiteral("to")).toObject());
    return to ? to->boardSerial : QString();
}
} // namespace

CfxForwarder::CfxForwarder(journal::Journal &journal, AmqpSender &sender, HandleOf handleOf,
                           Codec codec, Boards boards, QObject *parent)
    : QObject(parent)
    , m_journal(journal)
    , m_sender(sender)
    , m_handleOf(std::move(handleOf))
    , m_codec(codec)
    , m_boards(std::move(boards)) {
    m_waitTimer.setSingleShot(true);
    m_waitTimer.setInterval(kBoardCheckMs);
    connect(&m_waitTimer, &QTimer::timeout, this, &CfxForwarder::pumpSoon);
    m_pumpTimer.setSingleShot(true);
    m_pumpTimer.setInterval(20); // coalesces a burst of commits and acceptances
    connect(&m_pumpTimer, &QTimer::timeout, this, &CfxForwarder::pump);
    m_markTimer.setSingleShot(true);
    m_markTimer.setInterval(kMarkEveryMs);
    connect(&m_markTimer, &QTimer::timeout, this, &CfxForwarder::flushMarks);
    connect(&journal, &journal::Journal::committed, this, &CfxForwarder::pumpSoon);
    connect(&sender, &AmqpSender::connected, this, &CfxForwarder::pumpSoon);
    connect(&sender, &AmqpSender::disconnected, this, &CfxForwarder::onLost);
    connect(&sender, &AmqpSender::accepted, this, &CfxForwarder::onAccepted);
    connect(&sender, &AmqpSender::refused, this, [this](quint64 tag, const QString &reason) {
        // Left unsent in the journal: it goes out again with the next connection.
        if (m_inFlight.erase(tag))
            qCWarning(lcCfxForwarder, "the broker refused a CFX message: %s", qPrintable(reason));
    });
    pumpSoon();
}

void CfxForwarder::pumpSoon() {
    if (!m_pumpTimer.isActive())
        m_pumpTimer.start();
}

void CfxForwarder::pump() {
    if (m_sender.state() != AmqpSender::State::Connected)
        return;
    if (const auto opened = m_reader.keepOpen(m_journal.path()); !opened)
        return setProblem(opened.error());
    while (int(m_inFlight.size()) < kWindow) {
        const auto events = m_reader.unsentEvents(
            m_cursor, qMin(kBatch, kWindow - int(m_inFlight.size())), journal::SentChannel::Cfx);
        if (!events) {
            setProblem(events.error());
            return;
        }
        setProblem(QString());
        if (events->isEmpty())
            return;
        for (const journal::StoredEvent &event : *events) {
            if (event.record.kind == journal::JournalEvent::Kind::ContextChange &&
                !boardReady(event)) {
                m_waitTimer.start();
                return;
            }
            const std::optional<QList<Envelope>> made = envelopesOf(event);
            if (!made)
                return; // the journal could not be read: the event waits, the problem is said
            const QList<Envelope> &envelopes = *made;
            if (envelopes.isEmpty())
                markSoon(event.id);
            QList<quint64> tags;
            for (const Envelope &envelope : envelopes) {
                const quint64 tag = m_sender.send(toAmqpMessage(envelope, m_codec));
                if (tag == 0) { // the connection went meanwhile: it stays in the journal
                    for (const quint64 sent : tags)
                        m_inFlight.erase(sent);
                    return;
                }
                tags.append(tag);
                m_inFlight.emplace(tag, event.id);
            }
            if (!envelopes.isEmpty())
                m_unaccepted.insert(event.id, int(envelopes.size()));
            m_cursor = event.id;
        }
    }
}

std::optional<QList<Envelope>> CfxForwarder::envelopesOf(const journal::StoredEvent &stored) {
    if (stored.record.kind == journal::JournalEvent::Kind::ContextChange)
        return boardEnvelopesOf(stored);
    if (const std::optional<Envelope> envelope = faultEnvelopeOf(stored))
        return QList<Envelope>{*envelope};
    return QList<Envelope>();
}

std::optional<Envelope> CfxForwarder::faultEnvelopeOf(const journal::StoredEvent &stored) {
    const journal::JournalEvent &event = stored.record;
    if (!isFaultEvent(event))
        return std::nullopt;
    Message message;
    const QString place = faultPlace(event);
    if (event.severity != Severity::Info) {
        raised(stored);
        message = faultOccurred(fault(event, stored.uid));
    } else {
        const QUuid occurrence = raisingOccurrence(stored);
        if (occurrence.isNull())
            return std::nullopt; // its error was never a CFX fault (before CFX was on)
        message = faultCleared(occurrence);
    }
    return cfx::envelopeOf(message, m_handleOf(event.device), stored.uid,
                           QDateTime::fromMSecsSinceEpoch(event.timeMs, Qt::UTC));
}

std::optional<QList<Envelope>> CfxForwarder::boardEnvelopesOf(const journal::StoredEvent &change) {
    // The context changes before this one, newest first: the board they named last, and the
    // change that began naming it (its transaction).
    journal::EventFilter filter;
    filter.kinds = {journal::JournalEvent::Kind::ContextChange};
    filter.untilMs = change.record.timeMs + 1;
    filter.limit = kLookBack;
    filter.order = journal::Order::NewestFirst;
    const auto earlier = m_reader.events(filter);
    if (!earlier) {
        setProblem(earlier.error());
        return std::nullopt;
    }
    QString before;
    std::optional<journal::StoredEvent> began;
    for (const journal::StoredEvent &event : *earlier) {
        if (event.id >= change.id)
            continue;
        const QString serial = boardNamedBy(event);
        if (began && serial != before)
            break;
        before = serial;
        began = event;
    }
    const QString next = boardNamedBy(change);
    if (next == before)
        return QList<Envelope>(); // the same board: another operator or work order, or a program
                                  // started again

    const QList<model::DeviceIdentity> stations =
        m_boards.stations ? m_boards.stations() : QList<model::DeviceIdentity>();
    QList<Envelope> envelopes;
    const auto add = [&](const Message &message, const model::DeviceIdentity &station,
                         qint64 timeMs) {
        const QString handle = m_handleOf(station);
        envelopes.append(cfx::envelopeOf(
            message, handle,
            QUuid::createUuidV5(change.uid, QStringLiteral("%1/%2").arg(message.name, handle)),
            QDateTime::fromMSecsSinceEpoch(timeMs, Qt::UTC)));
    };
    if (!before.isEmpty()) {
        BoardWork work;
        work.serial = before;
        work.transaction = began->uid;
        work.workOrder = began->context.workOrder;
        work.startedMs = began->record.timeMs;
        work.finishedMs = change.record.timeMs;
        journal::JointFilter filter;
        filter.boardSerial = before;
        filter.sinceMs = work.startedMs;
        filter.untilMs = work.finishedMs + 1;
        filter.order = journal::Order::OldestFirst;
        const auto made = m_reader.joints(filter);
        if (!made) {
            setProblem(made.error());
            return std::nullopt;
        }
        // Each station that was told of the board, and each that made joints on it.
        QList<model::DeviceIdentity> workers = stations;
        for (const journal::StoredJoint &joint : *made)
            if (!workers.contains(joint.record.device))
                workers.append(joint.record.device);
        for (const model::DeviceIdentity &station : workers) {
            BoardWork own = work;
            for (const journal::StoredJoint &joint : *made)
                if (joint.record.device == station)
                    own.joints.append(joint);
            if (!own.joints.isEmpty())
                add(unitsProcessed(own), station, work.finishedMs);
            add(workCompleted(own), station, work.finishedMs);
        }
    }
    if (!next.isEmpty()) {
        BoardWork work;
        work.serial = next;
        work.transaction = change.uid;
        work.workOrder = change.context.workOrder;
        work.startedMs = change.record.timeMs;
        for (const model::DeviceIdentity &station : stations)
            add(workStarted(work), station, work.startedMs);
    }
    return envelopes;
}

bool CfxForwarder::boardReady(const journal::StoredEvent &change) {
    if (!m_boards.settled)
        return true;
    const qint64 nowMs = QDateTime::currentMSecsSinceEpoch();
    if (!m_waiting || m_waiting->row != change.id)
        m_waiting = Waiting{change.id, nowMs, std::nullopt};
    if (nowMs - m_waiting->sinceMs >= kBoardWaitMaxMs) {
        qCWarning(lcCfxForwarder,
                  "a board's messages waited %lld s for its last joints or stations: sent "
                  "without what had not come",
                  static_cast<long long>(kBoardWaitMaxMs / 1000));
        m_waiting.reset();
        return true;
    }
    if (!m_waiting->journalMark) {
        if (!m_boards.settled(change.record.timeMs))
            return false;
        m_waiting->journalMark = m_journal.appendedMark();
    }
    if (!m_journal.dealtWith(*m_waiting->journalMark))
        return false;
    m_waiting.reset();
    return true;
}

QUuid CfxForwarder::raisingOccurrence(const journal::StoredEvent &cleared) {
    const QString place = faultPlace(cleared.record);
    if (const auto it = m_openFaults.constFind(place); it != m_openFaults.cend())
        return m_openFaults.take(place).occurrence;
    journal::EventFilter filter;
    filter.deviceKey = cleared.record.device.key();
    filter.port = cleared.record.port;
    filter.kinds = {cleared.record.kind};
    filter.untilMs = cleared.record.timeMs + 1;
    filter.limit = kLookBack;
    filter.order = journal::Order::NewestFirst;
    const auto earlier = m_reader.events(filter);
    if (!earlier)
        return {};
    for (const journal::StoredEvent &event : *earlier) {
        if (event.id >= cleared.id)
            continue;
        if (event.record.severity == Severity::Info)
            return {}; // the last error here was cleared already
        return event.uid;
    }
    return {};
}

void CfxForwarder::onAccepted(quint64 tag) {
    const auto it = m_inFlight.find(tag);
    if (it == m_inFlight.end())
        return;
    const qint64 row = it->second;
    m_inFlight.erase(it);
    ++m_accepted;
    if (const auto left = m_unaccepted.find(row); left != m_unaccepted.end() && --*left == 0) {
        m_unaccepted.erase(left);
        markSoon(row);
    }
    pumpSoon();
}

void CfxForwarder::markSoon(qint64 row) {
    m_marks.append(row);
    if (!m_markTimer.isActive())
        m_markTimer.start();
}

void CfxForwarder::onLost() {
    // Everything from the oldest event not wholly accepted is read again after the next
    // connection; its messages keep their UniqueIDs.
    qint64 oldest = m_cursor;
    for (const auto &[tag, row] : m_inFlight)
        oldest = qMin(oldest, row - 1);
    m_inFlight.clear();
    m_unaccepted.clear();
    m_cursor = oldest;
    // Read again from the journal: what was raised before the cursor and not cleared is still
    // active, and the events after it are forwarded again.
    m_openFaults.clear();
    m_faultsRecalled = false;
}

void CfxForwarder::raised(const journal::StoredEvent &event) {
    m_openFaults.insert(faultPlace(event.record), {event.uid, m_handleOf(event.record.device),
                                                   fault(event.record, event.uid)});
}

// The faults raised and not cleared, from the journal's last fault events: at each place the
// newest decides. Those after the cursor are forwarded again and keep the same occurrence.
bool CfxForwarder::recallOpenFaults() {
    if (m_faultsRecalled)
        return true;
    if (const auto opened = m_reader.keepOpen(m_journal.path()); !opened)
        return false;
    journal::EventFilter filter;
    filter.kinds = {journal::JournalEvent::Kind::StationError,
                    journal::JournalEvent::Kind::PortError,
                    journal::JournalEvent::Kind::FeederError};
    filter.limit = kRecallEvents;
    filter.order = journal::Order::NewestFirst;
    const auto events = m_reader.events(filter);
    if (!events)
        return false;
    QSet<QString> decided;
    for (const journal::StoredEvent &event : *events) {
        const QString place = faultPlace(event.record);
        if (decided.contains(place))
            continue;
        decided.insert(place);
        if (event.record.severity != Severity::Info && !m_openFaults.contains(place))
            raised(event);
    }
    m_faultsRecalled = true;
    return true;
}

QJsonValue CfxForwarder::activeFaults(const QString &handle) {
    if (!recallOpenFaults())
        return QJsonValue(QJsonValue::Null);
    QList<const OpenFault *> here;
    for (const OpenFault &open : std::as_const(m_openFaults))
        if (open.handle == handle)
            here.append(&open);
    // Oldest first, as they were raised: a hash has no order of its own.
    std::sort(here.begin(), here.end(), [](const OpenFault *a, const OpenFault *b) {
        return a->fault.value(QStringLiteral("OccurredAt")).toString() <
               b->fault.value(QStringLiteral("OccurredAt")).toString();
    });
    QJsonArray faults;
    for (const OpenFault *open : std::as_const(here))
        faults.append(open->fault);
    return faults;
}

void CfxForwarder::flushMarks() {
    if (m_marks.isEmpty())
        return;
    const int count = int(m_marks.size());
    m_journal.markEventsSent(std::exchange(m_marks, {}), journal::SentChannel::Cfx);
    Q_EMIT forwarded(count);
}

void CfxForwarder::setProblem(const QString &problem) {
    if (problem == m_problem)
        return;
    m_problem = problem;
    Q_EMIT problemChanged(problem);
}

} // namespace tipscope::cfx
