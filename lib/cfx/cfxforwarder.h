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
// A station's board messages wait until its joints of the board are all in the journal: a joint
// begun before the change belongs to the board that ends (Journal::append) but is journaled only
// once it ended, seconds later. Boards::known says when the stations are all known (after a
// restart, before its lines found their stations, the board would reach only some of them);
// Boards::settled when one station has ended every joint it began before a time; the journal then
// has to have written what was appended until then. Each station's messages leave once it has,
// so a board change on many stations does not wait for the slowest: messages keep their order per
// endpoint, not across endpoints. While a station waits, the events after the change that are
// its own wait too, and so does the next board change; the others go on. The wait ends after
// kBoardWaitMaxMs whatever: a line that stays down must not hold the spool.
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
        // True once those stations are all known; none: at once.
        std::function<bool()> known;
        // True once the station has ended every joint it began before the time given (ms since
        // the epoch); none: at once.
        std::function<bool(const model::DeviceIdentity &station, qint64 timeMs)> settled;
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
    void pumpEvents();
    // The messages an event other than a context change becomes (none: it is marked at once),
    // or nothing when the journal could not be read to make them.
    [[nodiscard]] std::optional<QList<Envelope>> envelopesOf(const journal::StoredEvent &event);
    [[nodiscard]] std::optional<Envelope> faultEnvelopeOf(const journal::StoredEvent &event);
    // What a context change does to the board: the board it ends and the one it begins, empty
    // when it names the same board again; nothing when the journal could not be read.
    struct BoardChange {
        journal::StoredEvent change;
        QString ended;
        std::optional<journal::StoredEvent> endedBegan; // the change that began naming it
        QString begun;
        [[nodiscard]] bool changesBoard() const { return ended != begun; }
    };
    [[nodiscard]] std::optional<BoardChange> boardChangeOf(const journal::StoredEvent &change);
    // One station's messages of a board change: UnitsProcessed and WorkCompleted of the board
    // that ended, WorkStarted of the next if the station was told of it.
    [[nodiscard]] std::optional<QList<Envelope>>
    stationEnvelopesOf(const BoardChange &board, const model::DeviceIdentity &station,
                       bool toldOfNext);
    [[nodiscard]] QUuid raisingOccurrence(const journal::StoredEvent &cleared);
    void raised(const journal::StoredEvent &event);
    [[nodiscard]] bool recallOpenFaults();
    // The station's port status changes that BoardWork::statusChanges holds for a board made
    // from `sinceMs` to `untilMs`; nothing when the journal could not be read.
    [[nodiscard]] std::optional<QList<journal::StoredEvent>>
    statusChangesOf(const model::DeviceIdentity &station, qint64 sinceMs, qint64 untilMs);
    // Takes up a context change: false while it must wait for the stations to be known;
    // nothing when the journal could not be read.
    [[nodiscard]] std::optional<bool> openBoard(const journal::StoredEvent &change);
    // Sends the messages of each station of the open board that has settled; false when the
    // journal could not be read or the connection went.
    [[nodiscard]] bool advanceBoard();
    // False when the connection went meanwhile (what was handed over is forgotten). `station`:
    // the open board's station whose messages these are.
    [[nodiscard]] bool send(const QList<Envelope> &envelopes, qint64 row,
                            const model::DeviceIdentity *station = nullptr);
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
    // The board change under way: since when, the stations whose messages have not left (or
    // must leave again after a lost connection), the journal's mark taken when each settled, and
    // each one's messages not yet accepted.
    struct OpenBoard {
        BoardChange board;
        qint64 sinceMs = 0;
        bool stationsKnown = false;
        QList<model::DeviceIdentity> told; // of the board it begins
        QList<model::DeviceIdentity> waiting;
        QHash<model::DeviceIdentity, quint64> journalMarks;
        QHash<model::DeviceIdentity, int> unaccepted; // messages sent, not yet accepted
        QHash<quint64, model::DeviceIdentity> stationOfTag;
        bool overdueSaid = false;
        [[nodiscard]] qint64 row() const { return board.change.id; }
    };
    std::optional<OpenBoard> m_board;
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
