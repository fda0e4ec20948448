// EventLog: what happened on the line and the devices, with a timestamp and a plain
// explanation: station and port errors, alarms, status changes, writes and communication
// errors (NAKs with their meaning, timeouts, disconnects). Bounded: the oldest entries go first.
#pragma once

#include <QDateTime>
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
        Connection
    };
    enum class Severity { Info, Warning, Error };
    QDateTime time;
    Kind kind = Kind::Status;
    Severity severity = Severity::Info;
    QString source; // "DME-2C at 01, port 2"
    QString text;   // "Short circuit"

    // Stable English keys, for files other programs read (the support report).
    [[nodiscard]] static QString kindName(Kind kind);
    [[nodiscard]] static QString severityName(Severity severity);
    // For people, in the user's language: "Station error", "Write".
    [[nodiscard]] static QString kindTitle(Kind kind);
};

class EventLog : public QObject {
    Q_OBJECT
public:
    explicit EventLog(QObject *parent = nullptr, int capacity = 10000);

    void append(Event event);
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
    void cleared();

private:
    std::deque<Event> m_events;
    int m_capacity;
    qint64 m_dropped = 0;
    std::function<qint64()> m_clock;
};

} // namespace tipscope::model
