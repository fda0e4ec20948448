// The Errors page's history: the session's EventLog as a table (EventHistoryModel), one row per
// event, oldest first and bounded like the log, and a filter over it (EventHistoryFilter) by a set
// of kinds, a minimum severity and free text in any column.
#pragma once

#include "model/eventlog.h"

#include <QAbstractTableModel>
#include <QSortFilterProxyModel>
#include <deque>

namespace tipscope::gui {

constexpr quint32 eventKindBit(model::Event::Kind kind) {
    return 1u << int(kind);
}
constexpr quint32 kAllEventKinds = 0xffffffffu;
constexpr quint32 kErrorEventKinds =
    eventKindBit(model::Event::Kind::StationError) | eventKindBit(model::Event::Kind::PortError) |
    eventKindBit(model::Event::Kind::FeederError) | eventKindBit(model::Event::Kind::Alarm);

class EventHistoryModel : public QAbstractTableModel {
public:
    enum Column { Time, Severity, Kind, Source, Text, ColumnCount };
    // The same bound as the session's EventLog: the table never holds more than the log does.
    static constexpr int kCapacity = 10000;

    using QAbstractTableModel::QAbstractTableModel;

    void reset(const QList<model::Event> &events);
    // Appends in one insertion; above the capacity the oldest rows go first.
    void append(const QList<model::Event> &events);
    [[nodiscard]] const model::Event &event(int row) const { return m_events.at(size_t(row)); }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // What a cell says; `full` gives the date with the time, for files and the clipboard.
    [[nodiscard]] static QString text(const model::Event &e, int column, bool full);
    [[nodiscard]] static QString columnName(int column);

private:
    std::deque<model::Event> m_events;
};

class EventHistoryFilter : public QSortFilterProxyModel {
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

    // `kinds`: a set of eventKindBit()s; `text` is matched case-insensitively in any column.
    void setFilter(quint32 kinds, model::Event::Severity minimum, const QString &text);

protected:
    bool filterAcceptsRow(int row, const QModelIndex &parent) const override;

private:
    quint32 m_kinds = kAllEventKinds;
    model::Event::Severity m_minimum = model::Event::Severity::Info;
    QString m_text;
};

} // namespace tipscope::gui
