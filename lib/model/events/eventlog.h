// EventLog: what happened on the line and the devices, with a timestamp and a plain
// explanation: station and port errors, alarms, status changes, writes and communication
// errors (NAKs with their meaning, timeouts, disconnects). Bounded: the oldest entries go first.
//
// A flood collapses here, so that every reader (the history, the support report, the journal,
// MQTT) sees one entry: an event that says again what the latest entry of its source and kind
// says (same severity and text) within kRepeatWindowMs of its last time is not added; that entry
// counts it and moves its last time instead. appended() announces a new entry, repeated() a new
// count on an entry already announced (found again by its id, as its position can shift).
#pragma once

#include "model/context/deviceidentity.h"

#include <QDateTime>
#include <QJsonObject>
#include <QObject>
#include <deque>
#include <functional>

namespace tipscope::model {

struct Event {
    enum class Kind {
        StationError,
        PortError,
        FeederError,
        Alarm,
        Status,
        Write,
        Communication,
        Connection,
        ToolChange,
        // A joint outside its limits, or a tip that recovers more slowly than it did new.
        JointWarning,
        ProfileApply,
        // The journal's own, never in a device's log: the work context named another board,
        // operator or work order; the journal's reports about itself (records it could not keep).
        ContextChange,
        Journal
    };
    enum class Severity { Info, Warning, Error };

    Event() = default;
    Event(QDateTime time, Kind kind, Severity severity, QString source, QString text)
        : time(std::move(time))
        , kind(kind)
        , severity(severity)
        , source(std::move(source))
        , text(std::move(text)) {}

    QDateTime time;
    Kind kind = Kind::Status;
    Severity severity = Severity::Info;
    QString source; // "DME-2C at 01, port 2"
    QString text;   // "Short circuit"
    // The device whose history this is (empty for the line's own events) and its port (0: the
    // device itself). Two devices at one address on different lines, or one after the other,
    // have different identities even when their sources read the same.
    DeviceIdentity device;
    int port = 0;
    // What a program needs beyond the text (a profile apply's hash and changes); the journal
    // keeps it.
    QJsonObject details;
    // How often it happened (EventLog collapses a flood) and when it last did; lastTime equals
    // time while count is 1.
    int count = 1;
    QDateTime lastTime;
    // The log's sequence number: 1 for its first entry, never reused; 0 before the log has it.
    quint64 id = 0;

    // Whether `later` says again what this entry says (same kind, severity, device, port, source
    // and text).
    [[nodiscard]] bool isSaidAgainBy(const Event &later) const;

    // Stable English keys, for files other programs read (the support report).
    [[nodiscard]] static QString kindName(Kind kind);
    [[nodiscard]] static QString severityName(Severity severity);
    // For people, in the user's language: "Station error", "Write".
    [[nodiscard]] static QString kindTitle(Kind kind);
};

class EventLog : public QObject {
    Q_OBJECT
public:
    // Longest quiet time between two events that still counts them as one flood.
    static constexpr qint64 kRepeatWindowMs = 60'000;
    // How many of the newest entries are searched for the one an event repeats.
    static constexpr int kRepeatLookback = 256;

    explicit EventLog(QObject *parent = nullptr, int capacity = 10000);

    // An event without a time is stamped now, or `ageMs` before now for a change a device showed
    // in a reading that old (Parameter::reportedAgeMs): never before the newest entry.
    void append(Event event, double ageMs = 0);
    void add(Event::Kind kind, Event::Severity severity, const QString &source,
             const QString &text);
    [[nodiscard]] QList<Event> events() const;
    [[nodiscard]] int size() const { return int(m_events.size()); }
    [[nodiscard]] qint64 dropped() const { return m_dropped; }
    void clear();

    // Where an event without a time gets its time (milliseconds since the epoch). The session
    // hands in the clock its telemetry samples use, so a marker sits on the sample it explains
    // even after the wall clock was set; the default is the wall clock.
    void setClock(std::function<qint64()> msSinceEpoch);

Q_SIGNALS:
    void appended(const tipscope::model::Event &event);
    // `event` (an entry appended before, same id) happened again: its count and last time grew.
    void repeated(const tipscope::model::Event &event);
    void cleared();

private:
    // The entry `event` repeats, or null: the latest one of its source and kind, if it says the
    // same and its last time is recent enough.
    [[nodiscard]] Event *repeatTarget(const Event &event);

    std::deque<Event> m_events;
    int m_capacity;
    qint64 m_dropped = 0;
    quint64 m_lastId = 0;
    std::function<qint64()> m_clock;
};

} // namespace tipscope::model
