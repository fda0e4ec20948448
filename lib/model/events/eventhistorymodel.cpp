#include "eventhistorymodel.h"

#include "base/timetext.h"
#include "eventtext.h"

#include <QCoreApplication>
#include <algorithm>

namespace tipscope::model {

namespace {
struct EventHistoryModelTr {
    Q_DECLARE_TR_FUNCTIONS(EventHistoryModel)
};
} // namespace

void EventHistoryModel::reset(const QList<Event> &events) {
    beginResetModel();
    const qsizetype skip = qMax<qsizetype>(0, events.size() - kCapacity);
    m_events.assign(events.begin() + skip, events.end());
    endResetModel();
}

void EventHistoryModel::append(const QList<Event> &events) {
    const qsizetype skip = qMax<qsizetype>(0, events.size() - kCapacity);
    const int incoming = int(events.size() - skip);
    const int overflow = qMin(int(m_events.size()) + incoming - kCapacity, int(m_events.size()));
    if (overflow > 0) {
        beginRemoveRows({}, 0, overflow - 1);
        m_events.erase(m_events.begin(), m_events.begin() + overflow);
        endRemoveRows();
    }
    const int first = int(m_events.size());
    beginInsertRows({}, first, first + incoming - 1);
    m_events.insert(m_events.end(), events.begin() + skip, events.end());
    endInsertRows();
}

void EventHistoryModel::update(const QList<Event> &events) {
    for (const Event &e : events) {
        const auto at =
            std::lower_bound(m_events.begin(), m_events.end(), e.id,
                             [](const Event &shown, quint64 id) { return shown.id < id; });
        if (at == m_events.end() || at->id != e.id)
            continue;
        *at = e;
        const int row = int(at - m_events.begin());
        Q_EMIT dataChanged(index(row, 0), index(row, ColumnCount - 1));
    }
}

int EventHistoryModel::rowCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : int(m_events.size());
}

int EventHistoryModel::columnCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString EventHistoryModel::text(const Event &e, int column, bool full) {
    switch (column) {
    case Time:
        return full ? e.time.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz"))
                    : base::clockText(e.time);
    case Severity:
        return levelName(levelOf(e.severity));
    case Kind:
        return Event::kindTitle(e.kind);
    case Source:
        return e.source;
    case Text:
        return repeatedEventText(
            e.text, e.count,
            full ? e.lastTime.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz"))
                 : base::clockText(e.lastTime));
    default:
        return {};
    }
}

QVariant EventHistoryModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const Event &e = event(index.row());
    switch (role) {
    case Qt::DisplayRole:
        return text(e, index.column(), false);
    case Qt::ToolTipRole:
        if (index.column() == Source && !e.device.isEmpty())
            return e.device.description(); // two devices at one address read alike otherwise
        return index.column() == Time ? text(e, Time, true) : text(e, index.column(), false);
    case LevelRole:
        return int(levelOf(e.severity));
    default:
        return {};
    }
}

QVariant EventHistoryModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return columnName(section);
}

QString EventHistoryModel::columnName(int column) {
    switch (column) {
    case Time:
        return EventHistoryModelTr::tr("Time");
    case Severity:
        return EventHistoryModelTr::tr("Severity");
    case Kind:
        return EventHistoryModelTr::tr("Kind");
    case Source:
        return EventHistoryModelTr::tr("Source");
    case Text:
        return EventHistoryModelTr::tr("What happened");
    default:
        return {};
    }
}

void EventHistoryFilter::setFilter(quint32 kinds, Event::Severity minimum, const QString &text) {
    m_kinds = kinds;
    m_minimum = minimum;
    m_text = text.trimmed();
    invalidateFilter();
}

void EventHistoryFilter::setDevice(const QString &device) {
    m_device = device;
    invalidateFilter();
}

bool EventHistoryFilter::filterAcceptsRow(int row, const QModelIndex &) const {
    const Event &e = static_cast<const EventHistoryModel *>(sourceModel())->event(row);
    if (!m_device.isEmpty() && !e.device.isEmpty() && e.device.key() != m_device)
        return false;
    if (!(m_kinds & eventKindBit(e.kind)) || int(e.severity) < int(m_minimum))
        return false;
    if (m_text.isEmpty())
        return true;
    for (int c = 0; c < EventHistoryModel::ColumnCount; ++c)
        if (EventHistoryModel::text(e, c, true).contains(m_text, Qt::CaseInsensitive))
            return true;
    return false;
}

bool EventHistoryFilter::lessThan(const QModelIndex &left, const QModelIndex &right) const {
    return left.row() < right.row();
}

} // namespace tipscope::model
