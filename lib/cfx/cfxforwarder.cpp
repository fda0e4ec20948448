#include "cfxforwarder.h"

#include "amqpsender.h"
#include "cfxboard.h"
#include "cfxmessages.h"

#include "journal/journal.h"
#include "model/context/workcontextjson.h"

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
    pumpEvents();
    if (m_board) // a station still to settle, or stations still to be known
        m_waitTimer.start();
}

void CfxForwarder::pumpEvents() {
    if (m_board && m_board->stationsKnown && !advanceBoard())
        return;
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
            if (event.record.kind == journal::JournalEvent::Kind::ContextChange) {
                // One board change at a time: the next waits for every station of this one.
                if (m_board && m_board->row() != event.id)
                    return;
                const std::optional<bool> opened = openBoard(event);
                if (!opened || !*opened)
                    return;
                m_cursor = event.id;
                if (m_board && !advanceBoard())
                    return;
                continue;
            }
            // A station's own events keep their place behind its board messages.
            if (m_board && m_board->waiting.contains(event.record.device))
                return;
            const std::optional<QList<Envelope>> made = envelopesOf(event);
            if (!made)
                return; // the journal could not be read: the event waits, the problem is said
            if (made->isEmpty())
                markSoon(event.id);
            else if (!send(*made, event.id))
                return;
            m_cursor = event.id;
        }
    }
}

bool CfxForwarder::send(const QList<Envelope> &envelopes, qint64 row,
                        const model::DeviceIdentity *station) {
    QList<quint64> tags;
    for (const Envelope &envelope : envelopes) {
        const quint64 tag = m_sender.send(toAmqpMessage(envelope, m_codec));
        if (tag == 0) { // the connection went meanwhile: it stays in the journal
            for (const quint64 sent : tags)
                m_inFlight.erase(sent);
            return false;
        }
        tags.append(tag);
        m_inFlight.emplace(tag, row);
    }
    if (envelopes.isEmpty())
        return true;
    m_unaccepted[row] += int(envelopes.size());
    if (station && m_board && m_board->row() == row) {
        m_board->unaccepted[*station] += int(envelopes.size());
        for (const quint64 tag : tags)
            m_board->stationOfTag.insert(tag, *station);
    }
    return true;
}

std::optional<QList<Envelope>> CfxForwarder::envelopesOf(const journal::StoredEvent &stored) {
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

std::optional<CfxForwarder::BoardChange>
CfxForwarder::boardChangeOf(const journal::StoredEvent &change) {
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
    BoardChange board;
    board.change = change;
    for (const journal::StoredEvent &event : *earlier) {
        if (event.id >= change.id)
            continue;
        const QString serial = boardNamedBy(event);
        if (board.endedBegan && serial != board.ended)
            break;
        board.ended = serial;
        board.endedBegan = event;
    }
    // The same board named again: another operator or work order, or a program started again.
    board.begun = boardNamedBy(change);
    return board;
}

std::optional<QList<Envelope>>
CfxForwarder::stationEnvelopesOf(const BoardChange &board, const model::DeviceIdentity &station,
                                 bool toldOfNext) {
    const journal::StoredEvent &change = board.change;
    const QString handle = m_handleOf(station);
    QList<Envelope> envelopes;
    const auto add = [&](const Message &message, qint64 timeMs) {
        envelopes.append(cfx::envelopeOf(
            message, handle,
            QUuid::createUuidV5(change.uid, QStringLiteral("%1/%2").arg(message.name, handle)),
            QDateTime::fromMSecsSinceEpoch(timeMs, Qt::UTC)));
    };
    if (!board.ended.isEmpty()) {
        BoardWork work;
        work.serial = board.ended;
        work.transaction = board.endedBegan->uid;
        work.workOrder = board.endedBegan->context.workOrder;
        work.startedMs = board.endedBegan->record.timeMs;
        work.finishedMs = change.record.timeMs;
        journal::JointFilter filter;
        filter.boardSerial = board.ended;
        filter.deviceKey = station.key();
        filter.sinceMs = work.startedMs;
        filter.untilMs = work.finishedMs + 1;
        filter.order = journal::Order::OldestFirst;
        const auto made = m_reader.joints(filter);
        if (!made) {
            setProblem(made.error());
            return std::nullopt;
        }
        work.joints = *made;
        const auto changes = statusChangesOf(station, work.startedMs, work.finishedMs);
        if (!changes)
            return std::nullopt;
        work.statusChanges = *changes;
        if (!work.joints.isEmpty())
            add(unitsProcessed(work), work.finishedMs);
        add(workCompleted(work), work.finishedMs);
    }
    if (!board.begun.isEmpty() && toldOfNext) {
        BoardWork work;
        work.serial = board.begun;
        work.transaction = change.uid;
        work.workOrder = change.context.workOrder;
        work.startedMs = change.record.timeMs;
        add(workStarted(work), work.startedMs);
    }
    return envelopes;
}

std::optional<QList<journal::StoredEvent>>
CfxForwarder::statusChangesOf(const model::DeviceIdentity &station, qint64 sinceMs,
                              qint64 untilMs) {
    journal::EventFilter filter;
    filter.deviceKey = station.key();
    filter.kinds = {journal::JournalEvent::Kind::Status};
    // Each port's last change before the board says the status it began in.
    filter.untilMs = sinceMs;
    filter.limit = kLookBack;
    filter.order = journal::Order::NewestFirst;
    const auto before = m_reader.events(filter);
    filter.sinceMs = sinceMs;
    filter.untilMs = untilMs + 1;
    filter.limit = 0;
    filter.order = journal::Order::OldestFirst;
    const auto during = before ? m_reader.events(filter) : before;
    if (!during) {
        setProblem(during.error());
        return std::nullopt;
    }
    QList<journal::StoredEvent> changes;
    QSet<int> seen;
    for (const journal::StoredEvent &event : *before)
        if (event.record.port && !seen.contains(*event.record.port)) {
            seen.insert(*event.record.port);
            changes.prepend(event);
        }
    return changes + *during;
}

std::optional<bool> CfxForwarder::openBoard(const journal::StoredEvent &change) {
    const qint64 nowMs = QDateTime::currentMSecsSinceEpoch();
    if (!m_board || m_board->row() != change.id) {
        const std::optional<BoardChange> board = boardChangeOf(change);
        if (!board)
            return std::nullopt;
        if (!board->changesBoard()) {
            markSoon(change.id);
            return true;
        }
        m_board.emplace();
        m_board->board = *board;
        m_board->sinceMs = nowMs;
    }
    OpenBoard &open = *m_board;
    if (open.stationsKnown)
        return true; // read again after a lost connection: it is under way
    const bool overdue = nowMs - open.sinceMs >= kBoardWaitMaxMs;
    if (m_boards.known && !m_boards.known() && !overdue)
        return false;
    open.stationsKnown = true;
    open.told = m_boards.stations ? m_boards.stations() : QList<model::DeviceIdentity>();
    // Each station told of the board, and each that made joints on the board ended, told of it
    // or not.
    QList<model::DeviceIdentity> workers = open.told;
    if (!open.board.ended.isEmpty()) {
        journal::JointFilter filter;
        filter.boardSerial = open.board.ended;
        filter.sinceMs = open.board.endedBegan->record.timeMs;
        filter.untilMs = change.record.timeMs + 1;
        const auto made = m_reader.joints(filter);
        if (!made) {
            setProblem(made.error());
            m_board.reset();
            return std::nullopt;
        }
        for (const journal::StoredJoint &joint : *made)
            if (!workers.contains(joint.record.device))
                workers.append(joint.record.device);
    }
    open.waiting = workers;
    return true;
}

bool CfxForwarder::advanceBoard() {
    OpenBoard &open = *m_board;
    const qint64 nowMs = QDateTime::currentMSecsSinceEpoch();
    // Nothing to wait for when no board ended; a line that stays down must not hold the spool.
    const bool overdue = nowMs - open.sinceMs >= kBoardWaitMaxMs;
    const bool waitForJoints = !open.board.ended.isEmpty() && !overdue;
    if (overdue && !open.waiting.isEmpty() && !std::exchange(open.overdueSaid, true))
        qCWarning(lcCfxForwarder,
                  "a board's messages waited %lld s for the last joints of %lld station(s): sent "
                  "without what had not come",
                  static_cast<long long>(kBoardWaitMaxMs / 1000),
                  static_cast<long long>(open.waiting.size()));
    for (qsizetype i = 0; i < open.waiting.size();) {
        const model::DeviceIdentity station = open.waiting.at(i);
        if (waitForJoints) {
            auto mark = open.journalMarks.constFind(station);
            if (mark == open.journalMarks.cend()) {
                if (m_boards.settled &&
                    !m_boards.settled(station, open.board.change.record.timeMs)) {
                    ++i;
                    continue;
                }
                mark = open.journalMarks.insert(station, m_journal.appendedMark());
            }
            if (!m_journal.dealtWith(*mark)) {
                ++i;
                continue;
            }
        }
        const std::optional<QList<Envelope>> made =
            stationEnvelopesOf(open.board, station, open.told.contains(station));
        if (!made || !send(*made, open.row(), &station))
            return false;
        open.waiting.removeAt(i);
    }
    if (!open.waiting.isEmpty())
        return true;
    // Every station's messages have left: the change is marked once the broker took them all.
    if (!m_unaccepted.contains(open.row()))
        markSoon(open.row());
    m_board.reset();
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
    const bool boardOpen = m_board && m_board->row() == row;
    if (boardOpen) {
        const model::DeviceIdentity station = m_board->stationOfTag.take(tag);
        if (const auto left = m_board->unaccepted.find(station);
            left != m_board->unaccepted.end() && --*left == 0)
            m_board->unaccepted.erase(left);
    }
    if (const auto left = m_unaccepted.find(row); left != m_unaccepted.end() && --*left == 0) {
        m_unaccepted.erase(left);
        if (!boardOpen) // an open board's change is marked when its last station's messages left
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
    // An open board's stations whose messages the broker took stay done; the others send theirs
    // again, with the same UniqueIDs.
    if (m_board) {
        for (auto it = m_board->unaccepted.cbegin(); it != m_board->unaccepted.cend(); ++it)
            if (!m_board->waiting.contains(it.key()))
                m_board->waiting.append(it.key());
        m_board->unaccepted.clear();
        m_board->stationOfTag.clear();
    }
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
