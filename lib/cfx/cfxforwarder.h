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
// A change of the work context's board serial ends one board and begins the next (cfxboard.h):
// the board that was named gets UnitsProcessed and WorkCompleted from each station that follows
// the shared context or made joints on it, the new one WorkStarted from each that follows it.
// What was named before is the journal's previous context change, not the event's own "from":
// a program that starts again names its board again, and that continues the open work. The
// transaction is the id of the change that began the board. One event may so become several
// messages, each with a UniqueID made from the event's id, its message and its station; the
// event is marked sent when the broker accepted all of them.
//
// A board's messages wait (and the events after them) until its joints are all in the journal:
// a joint begun before the change belongs to the board that ends (Journal::append) but is
// journaled only once it ended, seconds later. Boards::settled says when the stations have
// ended every joint begun before a time and are all known (after a restart, before its lines
// found their stations, the board would reach only some of them); the journal then has to have
// written what was appended until then. The wait ends after kBoardWaitMaxMs whatever: a line
// that stays down must not hold the spool.
//
// The journal and the sender must outlive the forwarder, and live on its thread.
#pragma once

#include "cfxenvelope.h"

#include "journal/journalreader.h"

#include <QHash>
#include <QJsonObject>
#include <QJsonValue>
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
    struct Boards {
        // The stations that work on the board the shared work context names (those on lines
        // without a context of their own).
        std::function<QList<model::DeviceIdentity>()> stations;
        // True once those stations are all known and have ended every joint begun before the
        // time given (ms since the epoch); none: at once.
        std::function<bool(qint64 timeMs)> settled;
    };
    static constexpr int kWindow = 200;
    // The longest a board's messages wait for its last joints: a joint ends within
    // JointDetector::kGiveUpMs (30 s) and its tail, and is journaled within a second.
    static constexpr qint64 kBoardWaitMaxMs = 35'000;

    CfxForwarder(journal::Journal &journal, AmqpSender &sender, HandleOf handleOf, Codec codec,
                 Boards boards = {}, QObject *parent = nullptr);

    [[nodiscard]] qint64 acceptedCount() const { return m_accepted; }
    // The faults active at the endpoint `handle` (the SDK's Heartbeat.ActiveFaults): those raised
    // and not cleared, as the journal has them; after a restart they are read from the journal
    // again (its last kRecallEvents fault events). Null when the journal cannot be read.
    [[nodiscard]] QJsonValue activeFaults(const QString &handle);
    static constexpr int kRecallEvents = 2000;
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
    // The messages an event becomes (none: it is marked at once), or nothing when the journal
    // could not be read to make them.
    [[nodiscard]] std::optional<QList<Envelope>> envelopesOf(const journal::StoredEvent &event);
    [[nodiscard]] std::optional<Envelope> faultEnvelopeOf(const journal::StoredEvent &event);
    [[nodiscard]] std::optional<QList<Envelope>>
    boardEnvelopesOf(const journal::StoredEvent &change);
    [[nodiscard]] QUuid raisingOccurrence(const journal::StoredEvent &cleared);
    void raised(const journal::StoredEvent &event);
    [[nodiscard]] bool recallOpenFaults();
    // False while a context change must wait for its board's joints (then pump() is called
    // again soon).
    [[nodiscard]] bool boardReady(const journal::StoredEvent &change);
    void markSoon(qint64 row);
    void onAccepted(quint64 tag);
    void onLost();
    void flushMarks();
    void setProblem(const QString &problem);

    journal::Journal &m_journal;
    AmqpSender &m_sender;
    HandleOf m_handleOf;
    Codec m_codec;
    Boards m_boards;
    // The context change waiting for its board's joints: its row, since when it waits, and the
    // journal's mark once the stations had settled.
    struct Waiting {
        qint64 row = 0;
        qint64 sinceMs = 0;
        std::optional<quint64> journalMark;
    };
    std::optional<Waiting> m_waiting;
    QTimer m_waitTimer;
    journal::JournalReader m_reader;
    qint64 m_cursor = 0;
    std::map<quint64, qint64> m_inFlight; // tag → event row
    QHash<qint64, int> m_unaccepted;      // event row → its messages the broker has not accepted
    struct OpenFault {
        QUuid occurrence;
        QString handle;
        QJsonObject fault;
    };
    QHash<QString, OpenFault> m_openFaults; // faultPlace() → the fault raised there
    bool m_faultsRecalled = false;
    QList<qint64> m_marks;
    QTimer m_pumpTimer;
    QTimer m_markTimer;
    qint64 m_accepted = 0;
    QString m_problem;
};

} // namespace tipscope::cfx
