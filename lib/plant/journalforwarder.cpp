#include "journalforwarder.h"

#include "plantpayloads.h"

#include "journal/jointexport.h"
#include "journal/journal.h"
#include "mqtt/mqttclient.h"

#include <QJsonDocument>
#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcForwarder, "tipscope.plant.forwarder")

namespace tipscope::plant {

namespace {
constexpr int kBatch = 100;
constexpr int kMarkEveryMs = 200;
constexpr int kStallMs = 60000;
} // namespace

JournalForwarder::JournalForwarder(journal::Journal &journal, mqtt::MqttClient &client,
                                   PlaceOf placeOf, QObject *parent)
    : QObject(parent)
    , m_journal(journal)
    , m_client(client)
    , m_placeOf(std::move(placeOf)) {
    m_pumpTimer.setSingleShot(true);
    m_pumpTimer.setInterval(20); // coalesces a burst of commits and acknowledgements
    connect(&m_pumpTimer, &QTimer::timeout, this, &JournalForwarder::pump);
    m_markTimer.setSingleShot(true);
    m_markTimer.setInterval(kMarkEveryMs);
    connect(&m_markTimer, &QTimer::timeout, this, &JournalForwarder::flushMarks);
    m_stallTimer.setInterval(kStallMs / 4);
    connect(&m_stallTimer, &QTimer::timeout, this, &JournalForwarder::checkStalled);
    m_stallTimer.start();
    connect(&journal, &journal::Journal::committed, this, &JournalForwarder::pumpSoon);
    connect(&client, &mqtt::MqttClient::connected, this, [this] {
        m_sinceAck.restart(); // what waited through the outage gets a minute of its own
        pumpSoon();
    });
    connect(&client, &mqtt::MqttClient::published, this, &JournalForwarder::onPublished);
    connect(&client, &mqtt::MqttClient::publishRejected, this,
            [this](int id, const QString &reason) {
                // Left unsent: it goes out again after the next restart().
                if (m_inFlight.remove(id))
                    qCWarning(lcForwarder, "the broker refused a record: %s", qPrintable(reason));
            });
    m_sinceAck.start();
    pumpSoon();
}

void JournalForwarder::restart() {
    flushMarks();
    m_inFlight.clear();
    m_jointCursor = 0;
    m_eventCursor = 0;
    pumpSoon();
}

void JournalForwarder::pumpSoon() {
    if (!m_pumpTimer.isActive())
        m_pumpTimer.start();
}

void JournalForwarder::pump() {
    if (m_client.state() != mqtt::MqttClient::State::Connected)
        return;
    if (const auto opened = m_reader.keepOpen(m_journal.path()); !opened)
        return setProblem(opened.error());
    while (m_inFlight.size() < kWindow) {
        const int room = qMin(kBatch, kWindow - int(m_inFlight.size()));
        const auto joints = m_reader.unsentJoints(m_jointCursor, room);
        const auto events = m_reader.unsentEvents(m_eventCursor, room);
        if (!joints || !events) {
            setProblem(!joints ? joints.error() : events.error());
            return;
        }
        setProblem(QString());
        if (joints->isEmpty() && events->isEmpty())
            return;
        // The two lists merged by time, so a subscriber sees joints and events as they happened.
        qsizetype j = 0, e = 0;
        while (m_inFlight.size() < kWindow && (j < joints->size() || e < events->size())) {
            const bool takeJoint =
                e >= events->size() ||
                (j < joints->size() && joints->at(j).record.endMs <= events->at(e).record.timeMs);
            if (takeJoint) {
                const journal::StoredJoint &joint = joints->at(j++);
                const DevicePlace place = m_placeOf(joint.record.device);
                QJsonObject payload = journal::jointJson(joint);
                payload.insert(QStringLiteral("line"), place.line);
                payload.insert(QStringLiteral("connection"), joint.record.device.line);
                if (!publish(place.root + QStringLiteral("/joint"), payload, {true, joint.id}))
                    return;
                m_jointCursor = joint.id;
            } else {
                const journal::StoredEvent &event = events->at(e++);
                const DevicePlace place = m_placeOf(event.record.device);
                QJsonObject payload = eventPayload(event);
                payload.insert(QStringLiteral("line"), place.line);
                payload.insert(QStringLiteral("connection"), event.record.device.line);
                if (!publish(place.root + QStringLiteral("/event"), payload, {false, event.id}))
                    return;
                m_eventCursor = event.id;
            }
        }
    }
}

bool JournalForwarder::publish(const QString &topic, const QJsonObject &payload, InFlight item) {
    const auto sent =
        m_client.publish(topic, QJsonDocument(payload).toJson(QJsonDocument::Compact), 1, false);
    if (!sent.ok()) // disconnected, or the client's queue is full: it stays in the journal
        return false;
    if (m_inFlight.isEmpty())
        m_sinceAck.restart();
    m_inFlight.insert(sent.messageId, item);
    return true;
}

void JournalForwarder::onPublished(int messageId) {
    const auto it = m_inFlight.constFind(messageId);
    if (it == m_inFlight.cend())
        return;
    (it->joint ? m_sentJoints : m_sentEvents).append(it->row);
    m_inFlight.erase(it);
    m_sinceAck.restart();
    ++m_acknowledged;
    if (!m_markTimer.isActive())
        m_markTimer.start();
    pumpSoon();
}

void JournalForwarder::flushMarks() {
    if (m_sentJoints.isEmpty() && m_sentEvents.isEmpty())
        return;
    const int joints = int(m_sentJoints.size()), events = int(m_sentEvents.size());
    if (joints)
        m_journal.markJointsSent(std::exchange(m_sentJoints, {}));
    if (events)
        m_journal.markEventsSent(std::exchange(m_sentEvents, {}));
    Q_EMIT forwarded(joints, events);
}

void JournalForwarder::checkStalled() {
    if (m_inFlight.isEmpty() || m_client.state() != mqtt::MqttClient::State::Connected ||
        m_sinceAck.elapsed() < kStallMs)
        return;
    qCWarning(lcForwarder, "%d records unacknowledged for a minute; sending them again",
              int(m_inFlight.size()));
    restart();
}

void JournalForwarder::setProblem(const QString &problem) {
    if (problem == m_problem)
        return;
    m_problem = problem;
    Q_EMIT problemChanged(problem);
}

} // namespace tipscope::plant
