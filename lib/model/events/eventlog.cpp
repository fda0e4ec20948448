#include "eventlog.h"

#include <cmath>

#include <QCoreApplication>

namespace tipscope::model {

namespace {
struct EventTr {
    Q_DECLARE_TR_FUNCTIONS(Event)
};
} // namespace

QString Event::kindName(Kind kind) {
    switch (kind) {
    case Kind::StationError:
        return QStringLiteral("station error");
    case Kind::PortError:
        return QStringLiteral("port error");
    case Kind::FeederError:
        return QStringLiteral("feeder error");
    case Kind::Alarm:
        return QStringLiteral("alarm");
    case Kind::Status:
        return QStringLiteral("status");
    case Kind::Write:
        return QStringLiteral("write");
    case Kind::Communication:
        return QStringLiteral("communication");
    case Kind::Connection:
        return QStringLiteral("connection");
    case Kind::ToolChange:
        return QStringLiteral("tool change");
    case Kind::JointWarning:
        return QStringLiteral("joint warning");
    case Kind::ProfileApply:
        return QStringLiteral("profile apply");
    case Kind::ContextChange:
        return QStringLiteral("context change");
    case Kind::Journal:
        return QStringLiteral("journal");
    }
    return {};
}

QString Event::kindTitle(Kind kind) {
    switch (kind) {
    case Kind::StationError:
        return EventTr::tr("Station error");
    case Kind::PortError:
        return EventTr::tr("Port error");
    case Kind::FeederError:
        return EventTr::tr("Feeder error");
    case Kind::Alarm:
        return EventTr::tr("Alarm");
    case Kind::Status:
        return EventTr::tr("Status");
    case Kind::Write:
        return EventTr::tr("Write");
    case Kind::Communication:
        return EventTr::tr("Communication");
    case Kind::Connection:
        return EventTr::tr("Connection");
    case Kind::ToolChange:
        return EventTr::tr("Tool change");
    case Kind::JointWarning:
        return EventTr::tr("Joint");
    case Kind::ProfileApply:
        return EventTr::tr("Profile apply");
    case Kind::ContextChange:
        return EventTr::tr("Work context");
    case Kind::Journal:
        return EventTr::tr("Journal");
    }
    return {};
}

QString Event::severityName(Severity severity) {
    switch (severity) {
    case Severity::Info:
        return QStringLiteral("info");
    case Severity::Warning:
        return QStringLiteral("warning");
    case Severity::Error:
        return QStringLiteral("error");
    }
    return {};
}

bool Event::isSaidAgainBy(const Event &later) const {
    return later.kind == kind && later.severity == severity && later.source == source &&
           later.text == text && later.device == device && later.port == port;
}

EventLog::EventLog(QObject *parent, int capacity)
    : QObject(parent)
    , m_capacity(qMax(1, capacity)) {}

void EventLog::append(Event event, double ageMs) {
    if (!event.time.isValid()) {
        event.time =
            m_clock ? QDateTime::fromMSecsSinceEpoch(m_clock()) : QDateTime::currentDateTime();
        if (ageMs > 0) {
            event.time = event.time.addMSecs(-std::llround(ageMs));
            if (!m_events.empty())
                event.time = qMax(event.time, m_events.back().time);
        }
    }
    if (Event *earlier = repeatTarget(event)) {
        earlier->count += qMax(1, event.count);
        earlier->lastTime =
            qMax(earlier->lastTime, event.lastTime.isValid() ? event.lastTime : event.time);
        Q_EMIT repeated(*earlier);
        return;
    }
    if (!event.lastTime.isValid())
        event.lastTime = event.time;
    event.count = qMax(1, event.count);
    event.id = ++m_lastId;
    m_events.push_back(event);
    while (int(m_events.size()) > m_capacity) {
        m_events.pop_front();
        ++m_dropped;
    }
    Q_EMIT appended(event);
}

Event *EventLog::repeatTarget(const Event &event) {
    // Bounded, so that an event from a quiet source does not walk the whole log.
    int looked = 0;
    for (auto it = m_events.rbegin(); it != m_events.rend() && looked < kRepeatLookback;
         ++it, ++looked) {
        if (it->source != event.source || it->kind != event.kind || it->device != event.device)
            continue;
        if (!it->isSaidAgainBy(event))
            return nullptr;
        const qint64 quiet = it->lastTime.msecsTo(event.time);
        return quiet <= kRepeatWindowMs ? &*it : nullptr;
    }
    return nullptr;
}

void EventLog::add(Event::Kind kind, Event::Severity severity, const QString &source,
                   const QString &text) {
    append(Event(QDateTime(), kind, severity, source, text));
}

void EventLog::setClock(std::function<qint64()> msSinceEpoch) {
    m_clock = std::move(msSinceEpoch);
}

QList<Event> EventLog::events() const {
    return QList<Event>(m_events.begin(), m_events.end());
}

void EventLog::clear() {
    m_events.clear();
    Q_EMIT cleared();
}

} // namespace tipscope::model
