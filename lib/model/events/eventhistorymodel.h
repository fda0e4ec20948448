// The session's EventLog as a table (EventHistoryModel), one row per entry, oldest first and
// bounded like the log, and a filter over it (EventHistoryFilter) by a set of kinds, a minimum
// severity, one device and free text in any column, which sorts by arrival (descending: the
// newest first). Any front end can show it: each cell has its
// text and the event's Level (LevelRole); how a level looks (icon, tint) is the front end's
// business. A collapsed flood (EventLog::repeated) is one row whose text says how often and until
// when.
#pragma once

#include "eventlog.h"
#include "problemlevel.h"

#include <QAbstractTableModel>
#include <QSortFilterProxyModel>
#include <deque>

namespace tipscope::model {

constexpr quint32 eventKindBit(Event::Kind kind) {
    return 1u << int(kind);
}
constexpr quint32 kAllEventKinds = 0xffffffffu;
constexpr quint32 kErrorEventKinds =
    eventKindBit(Event::Kind::StationError) | eventKindBit(Event::Kind::PortError) |
    eventKindBit(Event::Kind::FeederError) | eventKindBit(Event::Kind::Alarm);

class EventHistoryModel : public QAbstractTableModel {
public:
    enum Column { Time, Severity, Kind, Source, Text, ColumnCount };
    // The event's Level (an int), in every column.
    static constexpr int LevelRole = Qt::UserRole;
    // The same bound as the session's EventLog: the table never holds more than the log does.
    static constexpr int kCapacity = 10000;

    using QAbstractTableModel::QAbstractTableModel;

    void reset(const QList<Event> &events);
    // Appends in one insertion; above the capacity the oldest rows go first.
    void append(const QList<Event> &events);
    // Entries already shown that happened again (EventLog::repeated): found by id and replaced;
    // an entry no longer in the table is ignored.
    void update(const QList<Event> &events);
    [[nodiscard]] const Event &event(int row) const { return m_events.at(size_t(row)); }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // What a cell says; `full` gives the date with the time, for files and the clipboard; else
    // the date shows only when it is not today. A repeated event's text ends with its count
    // and its last time: "… (75 times, until 10:02:13)".
    [[nodiscard]] static QString text(const Event &e, int column, bool full);
    [[nodiscard]] static QString columnName(int column);

private:
    std::deque<Event> m_events;
};

class EventHistoryFilter : public QSortFilterProxyModel {
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

    // `kinds`: a set of eventKindBit()s; `text` is matched case-insensitively in any column.
    void setFilter(quint32 kinds, Event::Severity minimum, const QString &text);
    // Only the events of `device` (an identity key) and of the line itself; empty: every device.
    void setDevice(const QString &device);

protected:
    bool filterAcceptsRow(int row, const QModelIndex &parent) const override;
    // By arrival (the table's own order), whatever the column: sorted descending, the newest
    // event comes first.
    bool lessThan(const QModelIndex &left, const QModelIndex &right) const override;

private:
    quint32 m_kinds = kAllEventKinds;
    Event::Severity m_minimum = Event::Severity::Info;
    QString m_text;
    QString m_device;
};

} // namespace tipscope::model
