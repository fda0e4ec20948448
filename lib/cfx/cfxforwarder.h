// CfxForwarder: the journal's station, port and feeder errors to a CFX broker, with store and
// forward: the CFX sibling of plant/journalforwarder.h, with a sent mark of its own in the
// journal (SentChannel::Cfx), so a plant can run MQTT and CFX side by side, each taking every
// record once.
//
// An error event becomes ResourcePerformance.FaultOccurred, its "error cleared" event
// FaultCleared with the same FaultOccurrenceId (the raising event's id, found in the journal
// again after a restart). Each message's UniqueID is its event's id, fixed when the event was
// journaled, and its TimeStamp the event's time, so a message sent again after an outage or a
// crash is the same message. Events leave in the journal's order; an event is marked sent only
// when the broker accepted its message (AmqpSender::accepted()); events CFX has no message for
// are marked at once. At most kWindow messages wait for the broker; the rest wait in the journal.
// A lost connection sends everything not yet accepted again after the next one.
//
// The journal and the sender must outlive the forwarder, and live on its thread.
#pragma once

#include "cfxenvelope.h"

#include "journal/journalreader.h"

#include <QHash>
#include <QObject>
#include <QTimer>
#include <functional>
#include <map>

namespace tipscope::journal {
class Journal;
}

namespace tipscope::cfx {

class AmqpSender;

class CfxForwarder : public QObject {
    Q_OBJECT
public:
    // The CFX handle of the endpoint a device's records are sent as.
    using HandleOf = std::function<QString(const model::DeviceIdentity &device)>;
    static constexpr int kWindow = 200;

    CfxForwarder(journal::Journal &journal, AmqpSender &sender, HandleOf handleOf, Codec codec,
                 QObject *parent = nullptr);

    [[nodiscard]] qint64 acceptedCount() const { return m_accepted; }
    [[nodiscard]] int waitingCount() const { return int(m_inFlight.size()); }
    // Why the journal could not be read, empty when it could.
    [[nodiscard]] QString problem() const { return m_problem; }

Q_SIGNALS:
    // After messages were accepted and their events marked sent.
    void forwarded(int messages);
    void problemChanged(const QString &problem);

private:
    void pumpSoon();
    void pump();
    // The message an event becomes, or none (marked at once).
    [[nodiscard]] std::optional<Envelope> envelopeOf(const journal::StoredEvent &event);
    [[nodiscard]] QUuid raisingOccurrence(const journal::StoredEvent &cleared);
    void onAccepted(quint64 tag);
    void onLost();
    void flushMarks();
    void setProblem(const QString &problem);

    journal::Journal &m_journal;
    AmqpSender &m_sender;
    HandleOf m_handleOf;
    Codec m_codec;
    journal::JournalReader m_reader;
    qint64 m_cursor = 0;
    std::map<quint64, qint64> m_inFlight; // tag → event row
    QHash<QString, QUuid> m_openFaults;   // faultPlace() → occurrence
    QList<qint64> m_marks;
    QTimer m_pumpTimer;
    QTimer m_markTimer;
    qint64 m_accepted = 0;
    QString m_problem;
};

} // namespace tipscope::cfx
