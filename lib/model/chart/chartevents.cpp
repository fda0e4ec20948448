#include "model/chart/chartevents.h"

#include <algorithm>

namespace tipscope::model {

namespace {
// Stable tokens for the CSV, independent of the interface language.
struct KindToken {
    Event::Kind kind;
    const char *token;
};
constexpr KindToken kKindTokens[] = {
    {Event::Kind::Status, "status"},
    {Event::Kind::PortError, "port-error"},
    {Event::Kind::StationError, "station-error"},
    {Event::Kind::FeederError, "feeder-error"},
    {Event::Kind::Alarm, "alarm"},
    {Event::Kind::Write, "write"},
};

bool byTime(const ChartEvent &a, const ChartEvent &b) {
    return a.timeMs < b.timeMs;
}
} // namespace

bool ChartEvent::isMarked(Event::Kind kind) {
    return std::any_of(std::begin(kKindTokens), std::end(kKindTokens),
                       [kind](const KindToken &t) { return t.kind == kind; });
}

bool ChartEvent::concerns(const ChartChannel &channel) const {
    return scope == channel.id || scope == QLatin1Char('@') + channel.address;
}

QString ChartEvent::toCsvCell() const {
    for (const KindToken &t : kKindTokens)
        if (t.kind == kind)
            return scope + QLatin1Char(' ') + QLatin1String(t.token) + QStringLiteral(": ") + text;
    return {};
}

std::optional<ChartEvent> ChartEvent::fromCsvCell(qint64 timeMs, const QString &cell) {
    const qsizetype space = cell.indexOf(QLatin1Char(' '));
    const qsizetype colon = cell.indexOf(QStringLiteral(": "), space + 1);
    if (space <= 0 || colon < 0)
        return std::nullopt;
    const QString token = cell.mid(space + 1, colon - space - 1);
    for (const KindToken &t : kKindTokens) {
        if (token != QLatin1String(t.token))
            continue;
        ChartEvent e;
        e.timeMs = timeMs;
        e.kind = t.kind;
        e.scope = cell.left(space);
        e.text = cell.mid(colon + 2);
        const bool isError = t.kind == Event::Kind::PortError ||
                             t.kind == Event::Kind::StationError ||
                             t.kind == Event::Kind::FeederError;
        e.severity = t.kind == Event::Kind::Alarm ? Event::Severity::Warning
                     : isError                    ? Event::Severity::Error
                                                  : Event::Severity::Info;
        return e;
    }
    return std::nullopt;
}

std::optional<ChartEvent> ChartEvents::addFromLog(const Event &event,
                                                  const QList<ChartChannel> &channels) {
    if (!ChartEvent::isMarked(event.kind))
        return std::nullopt;
    QString scope;
    for (const ChartChannel &c : channels) {
        const QString device = c.deviceName;
        if (event.source == device) {
            scope = QLatin1Char('@') + c.address;
            break;
        }
        // The log names a port as "<device>, port <n>" (DeviceModel::sourceName); only the
        // number is compared, so a translated "port" still matches.
        if (!c.isFeeder() && event.source.startsWith(device + QStringLiteral(", ")) &&
            event.source.section(QLatin1Char(' '), -1).toInt() == c.port) {
            scope = c.id;
            break;
        }
    }
    if (scope.isEmpty())
        return std::nullopt;
    const ChartEvent added{event.time.toMSecsSinceEpoch(), event.kind, event.severity, scope,
                           event.text};
    add(added);
    return added;
}

void ChartEvents::add(ChartEvent event) {
    // Events come in time order, so this is an append but for the odd late one.
    const auto at = std::upper_bound(m_events.begin(), m_events.end(), event, byTime);
    m_events.insert(at, std::move(event));
    while (int(m_events.size()) > kCapacity)
        m_events.pop_front();
}

QList<ChartEvent> ChartEvents::between(qint64 t0, qint64 t1, const ChartChannel *channel) const {
    QList<ChartEvent> out;
    ChartEvent key;
    key.timeMs = t0;
    auto it = std::lower_bound(m_events.begin(), m_events.end(), key, byTime);
    for (; it != m_events.end() && it->timeMs < t1; ++it)
        if (!channel || it->concerns(*channel))
            out.append(*it);
    return out;
}

} // namespace tipscope::model
