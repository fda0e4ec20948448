// ChartEvents: the events worth a marker on the time axis (status changes, errors, alarms,
// parameter writes), kept sorted by time, so a redraw finds the markers of its window by binary
// search instead of copying the event log.
//
// The live chart keeps the newest kLiveCapacity events, as the event log itself is bounded. A
// replay keeps every event of its file (Unbounded): the file's size bounds them, and an event
// takes about its CSV size in memory (its texts are held as UTF-8, one allocation for all).
//
// Each event has a scope: the channel it concerns ("port3", "feeder") or a whole device
// ("@01": station errors and writes, which name no port). Live events get their scope from the
// event's device identity and port, and concern only the channels of that very device (another
// device once at the same address keeps its markers to itself); replayed ones from the CSV. The CSV
// form of an event is one cell, "port3 status: Working → Stand" (scope, kind token, text).
#pragma once

#include "model/chart/chartseries.h"

#include "model/events/eventlog.h"

#include <deque>
#include <optional>

namespace tipscope::model {

struct ChartEvent {
    qint64 timeMs = 0;
    Event::Kind kind = Event::Kind::Status;
    Event::Severity severity = Event::Severity::Info;
    QString scope;
    QString text;
    // The identity key of the device it happened on (live events); empty when the file it came
    // from names one device per channel anyway (a replay).
    QString device;

    [[nodiscard]] bool concerns(const ChartChannel &channel) const;
    [[nodiscard]] QString toCsvCell() const;
    // A marked kind of event from the log, scoped by matching its source to `channels`; nullopt
    // for other kinds and for events of no known channel.
    [[nodiscard]] static std::optional<ChartEvent> fromLog(const Event &event,
                                                           const QList<ChartChannel> &channels);
    // nullopt when the cell is not "scope kind: text" with a known kind.
    [[nodiscard]] static std::optional<ChartEvent> fromCsvCell(qint64 timeMs, const QString &cell);
    // Whether events of this kind get a marker (connection and communication notes do not).
    [[nodiscard]] static bool isMarked(Event::Kind kind);
};

class ChartEvents {
public:
    static constexpr qsizetype kLiveCapacity = 10000;
    static constexpr qsizetype kUnbounded = -1;

    // The newest `capacity` events are kept (all with kUnbounded).
    explicit ChartEvents(qsizetype capacity = kLiveCapacity)
        : m_capacity(capacity) {}

    // Adds ChartEvent::fromLog() of the event, and returns it.
    std::optional<ChartEvent> addFromLog(const Event &event, const QList<ChartChannel> &channels);
    void add(const ChartEvent &event);
    void clear();
    [[nodiscard]] qsizetype size() const { return qsizetype(m_entries.size()); }
    [[nodiscard]] qsizetype capacity() const { return m_capacity; }
    // Heap bytes held for the events.
    [[nodiscard]] qint64 memoryBytes() const;

    // The events of [t0, t1), oldest first; with `channel`, only those concerning it.
    [[nodiscard]] QList<ChartEvent> between(qint64 t0, qint64 t1,
                                            const ChartChannel *channel = nullptr) const;

private:
    // An event's scope and text sit in m_texts (UTF-8, the scope first).
    struct Entry {
        qint64 timeMs = 0;
        quint32 offset = 0;
        quint32 textBytes = 0;
        quint32 scopeBytes = 0;
        quint8 kind = 0;     // Event::Kind
        quint8 severity = 0; // Event::Severity
        quint16 device = 0;  // index into m_devices
    };

    [[nodiscard]] ChartEvent eventAt(const Entry &entry) const;
    void dropOldest();
    void compactTexts();

    qsizetype m_capacity;
    std::deque<Entry> m_entries;
    QByteArray m_texts;
    // The devices events were seen on; few per session, so each entry holds an index.
    QStringList m_devices;
    qint64 m_deadBytes = 0; // of m_texts, no longer used by an entry
};

} // namespace tipscope::model
