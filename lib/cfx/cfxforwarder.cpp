#include "cfxforwarder.h"

#include "amqpsender.h"
#include "cfxmessages.h"

#include "journal/journal.h"

#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcCfxForwarder, "tipscope.cfx.forwarder")

namespace tipscope::cfx {

namespace {
constexpr int kBatch = 100;
constexpr int kMarkEveryMs = 200;
// How far back a clearing looks for the error it clears, after a restart forgot it.
constexpr int kLookBack = 50;

using Severity = journal::JournalEvent::Severity;
} // namespace

CfxForwarder::CfxForwarder(journal::Journal &journal, AmqpSender &sender, HandleOf handleOf,
                           Codec codec, QObject *parent)
    : QObject(parent)
    , m_journal(journal)
    , m_sender(sender)
    , m_handleOf(std::move(handleOf))
    , m_codec(codec) {
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
            if (const std::optional<Envelope> envelope = envelopeOf(event)) {
                const quint64 tag = m_sender.send(toAmqpMessage(*envelope, m_codec));
                if (tag == 0) // the connection went meanwhile: it stays in the journal
                    return;
                m_inFlight.emplace(tag, event.id);
            } else {
                m_marks.append(event.id);
                if (!m_markTimer.isActive())
                    m_markTimer.start();
            }
            m_cursor = event.id;
        }
    }
}

std::optional<Envelope> CfxForwarder::envelopeOf(const journal::StoredEvent &stored) {
    const journal::JournalEvent &event = stored.record;
    if (!isFaultEvent(event))
        return std::nullopt;
    Message message;
    const QString place = faultPlace(event);
    if (event.severity != Severity::Info) {
        m_openFaults.insert(place, stored.uid);
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

QUuid CfxForwarder::raisingOccurrence(const journal::StoredEvent &cleared) {
    const QString place = faultPlace(cleared.record);
    if (const auto it = m_openFaults.constFind(place); it != m_openFaults.cend())
        return m_openFaults.take(place);
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
    m_marks.append(it->second);
    m_inFlight.erase(it);
    ++m_accepted;
    if (!m_markTimer.isActive())
        m_markTimer.start();
    pumpSoon();
}

void CfxForwarder::onLost() {
    // Everything from the oldest message not accepted is read again after the next connection.
    qint64 oldest = m_cursor;
    for (const auto &[tag, row] : m_inFlight)
        oldest = qMin(oldest, row - 1);
    m_inFlight.clear();
    m_cursor = oldest;
    m_openFaults.clear(); // read again with the events
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
