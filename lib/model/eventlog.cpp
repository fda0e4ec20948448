#include "eventlog.h"

namespace tipscope::model {

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

EventLog::EventLog(QObject *parent, int capacity)
    : QObject(parent)
    , m_capacity(qMax(1, capacity)) {}

void EventLog::append(Event event) {
    if (!event.time.isValid())
        event.time = QDateTime::currentDateTime();
    m_events.push_back(event);
    while (int(m_events.size()) > m_capacity) {
        m_events.pop_front();
        ++m_dropped;
    }
    Q_EMIT appended(event);
}

void EventLog::add(Event::Kind kind, Event::Severity severity, const QString &source,
                   const QString &text) {
    append({QDateTime::currentDateTime(), kind, severity, source, text});
}

QList<Event> EventLog::events() const {
    return QList<Event>(m_events.begin(), m_events.end());
}

void EventLog::clear() {
    m_events.clear();
    Q_EMIT cleared();
}

} // namespace tipscope::model
