// ChartEvents: the events worth a marker on the time axis (status changes, errors, alarms,
// parameter writes), kept sorted by time and bounded, so a redraw finds the markers of its window
// by binary search instead of copying the event log.
//
// Each event has a scope: the channel it concerns ("port3", "feeder") or a whole device
// ("@01": station errors and writes, which name no port). Live events get their scope from the
// event log's source text ("DME-4C at 01, port 3"); replayed ones from the CSV. The CSV form of
// an event is one cell, "port3 status: Working → Stand" (scope, kind token, text).
#pragma once

#include "model/chart/chartseries.h"

#include "model/eventlog.h"

#include <deque>
#include <optional>

namespace tipscope::model {

struct ChartEvent {
    qint64 timeMs = 0;
    Event::Kind kind = Event::Kind::Status;
    Event::Severity severity = Event::Severity::Info;
    QString scope;
    QString text;

    [[nodiscard]] bool concerns(const ChartChannel &channel) const;
    [[nodiscard]] QString toCsvCell() const;
    // nullopt when the cell is not "scope kind: text" with a known kind.
    [[nodiscard]] static std::optional<ChartEvent> fromCsvCell(qint64 timeMs, const QString &cell);
    // Whether events of this kind get a marker (connection and communication notes do not).
    [[nodiscard]] static bool isMarked(Event::Kind kind);
};

class ChartEvents {
public:
    static constexpr int kCapacity = 10000;

    // Adds a marked kind of event from the log, scoped by matching its source to `channels`, and
    // returns it; other kinds, and events of no known channel, are ignored (nullopt).
    std::optional<ChartEvent> addFromLog(const Event &event, const QList<ChartChannel> &channels);
    void add(ChartEvent event);
    void clear() { m_events.clear(); }
    [[nodiscard]] int size() const { return int(m_events.size()); }

    // The events of [t0, t1), oldest first; with `channel`, only those concerning it.
    [[nodiscard]] QList<ChartEvent> between(qint64 t0, qint64 t1,
                                            const ChartChannel *channel = nullptr) const;

private:
    std::deque<ChartEvent> m_events;
};

} // namespace tipscope::model
