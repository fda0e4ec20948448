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
} // namespace

bool ChartEvent::isMarked(Event::Kind kind) {
    return std::any_of(std::begin(kKindTokens), std::end(kKindTokens),
                       [kind](const KindToken &t) { return t.kind == kind; });
}

bool ChartEvent::concerns(const ChartChannel &channel) const {
    if (!device.isEmpty() && device != channel.device.key())
        return false;
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

std::optional<ChartEvent> ChartEvent::fromLog(const Event &event,
                                              const QList<ChartChannel> &channels) {
    if (!isMarked(event.kind))
        return std::nullopt;
    QString scope;
    for (const ChartChannel &c : channels) {
        if (event.device.isEmpty() || event.device != c.device)
            continue;
        if (event.port == 0) {
            scope = QLatin1Char('@') + c.address;
            break;
        }
        if (!c.isFeeder() && event.port == c.port) {
            scope = c.id;
            break;
        }
    }
    if (scope.isEmpty())
        return std::nullopt;
    return ChartEvent{event.time.toMSecsSinceEpoch(),
                      event.kind,
                      event.severity,
                      scope,
                      event.text,
                      event.device.key()};
}

std::optional<ChartEvent> ChartEvents::addFromLog(const Event &event,
                                                  const QList<ChartChannel> &channels) {
    auto added = ChartEvent::fromLog(event, channels);
    if (added)
        add(*added);
    return added;
}

void ChartEvents::add(const ChartEvent &event) {
    const QByteArray scope = event.scope.toUtf8();
    const QByteArray text = event.text.toUtf8();
    Entry entry;
    entry.timeMs = event.timeMs;
    entry.offset = quint32(m_texts.size());
    entry.scopeBytes = quint32(scope.size());
    entry.textBytes = quint32(text.size());
    entry.kind = quint8(event.kind);
    entry.severity = quint8(event.severity);
    if (!event.device.isEmpty()) {
        qsizetype index = m_devices.indexOf(event.device);
        if (index < 0) {
            m_devices.append(event.device);
            index = m_devices.size() - 1;
        }
        entry.device = quint16(qMin<qsizetype>(index + 1, 0xFFFF));
    }
    m_texts.append(scope).append(text);
    // Events come in time order, so this is an append but for the odd late one.
    const auto at = std::upper_bound(m_entries.begin(), m_entries.end(), entry.timeMs,
                                     [](qint64 t, const Entry &e) { return t < e.timeMs; });
    m_entries.insert(at, entry);
    while (m_capacity >= 0 && qsizetype(m_entries.size()) > m_capacity)
        dropOldest();
}

void ChartEvents::clear() {
    m_entries.clear();
    m_devices.clear();
    m_texts.clear();
    m_deadBytes = 0;
}

void ChartEvents::dropOldest() {
    const Entry &oldest = m_entries.front();
    m_deadBytes += qint64(oldest.scopeBytes) + qint64(oldest.textBytes);
    m_entries.pop_front();
    // The live store drops one event for each it adds: copy the texts still in use now and then
    // rather than let the dropped ones pile up.
    if (m_deadBytes > 64 * 1024 && m_deadBytes * 2 > m_texts.size())
        compactTexts();
}

void ChartEvents::compactTexts() {
    QByteArray kept;
    kept.reserve(m_texts.size() - m_deadBytes);
    for (Entry &e : m_entries) {
        const quint32 offset = quint32(kept.size());
        kept.append(m_texts.constData() + e.offset, qsizetype(e.scopeBytes) + e.textBytes);
        e.offset = offset;
    }
    m_texts = kept;
    m_deadBytes = 0;
}

ChartEvent ChartEvents::eventAt(const Entry &e) const {
    const char *scope = m_texts.constData() + e.offset;
    return ChartEvent{e.timeMs,
                      Event::Kind(e.kind),
                      Event::Severity(e.severity),
                      QString::fromUtf8(scope, e.scopeBytes),
                      QString::fromUtf8(scope + e.scopeBytes, qsizetype(e.textBytes)),
                      e.device > 0 ? m_devices.value(e.device - 1) : QString()};
}

qint64 ChartEvents::memoryBytes() const {
    // A deque allocates its entries in blocks of 512 bytes, plus a map of those blocks.
    const qint64 blocks = qint64(m_entries.size()) * qint64(sizeof(Entry)) / 512 + 1;
    return blocks * (512 + qint64(sizeof(void *))) + m_texts.capacity();
}

QList<ChartEvent> ChartEvents::between(qint64 t0, qint64 t1, const ChartChannel *channel) const {
    QList<ChartEvent> out;
    auto it = std::lower_bound(m_entries.begin(), m_entries.end(), t0,
                               [](const Entry &e, qint64 t) { return e.timeMs < t; });
    for (; it != m_entries.end() && it->timeMs < t1; ++it) {
        ChartEvent event = eventAt(*it);
        if (!channel || event.concerns(*channel))
            out.append(std::move(event));
    }
    return out;
}

} // namespace tipscope::model
