#include "journalevent.h"

namespace tipscope::journal {

namespace {

using Kind = JournalEvent::Kind;
using Severity = JournalEvent::Severity;

constexpr Severity kSeverities[] = {Severity::Info, Severity::Warning, Severity::Error};

Kind kindOf(model::Event::Kind kind) {
    switch (kind) {
    case model::Event::Kind::StationError:
        return Kind::StationError;
    case model::Event::Kind::PortError:
        return Kind::PortError;
    case model::Event::Kind::FeederError:
        return Kind::FeederError;
    case model::Event::Kind::Alarm:
        return Kind::Alarm;
    case model::Event::Kind::Status:
        return Kind::Status;
    case model::Event::Kind::Write:
        return Kind::Write;
    case model::Event::Kind::Communication:
        return Kind::Communication;
    case model::Event::Kind::Connection:
        return Kind::Connection;
    case model::Event::Kind::ToolChange:
        return Kind::ToolChange;
    case model::Event::Kind::Joint:
        return Kind::JointWarning;
    }
    return Kind::Status;
}

} // namespace

QString JournalEvent::kindName(Kind kind) {
    switch (kind) {
    case Kind::StationError:
        return model::Event::kindName(model::Event::Kind::StationError);
    case Kind::PortError:
        return model::Event::kindName(model::Event::Kind::PortError);
    case Kind::FeederError:
        return model::Event::kindName(model::Event::Kind::FeederError);
    case Kind::Alarm:
        return model::Event::kindName(model::Event::Kind::Alarm);
    case Kind::Status:
        return model::Event::kindName(model::Event::Kind::Status);
    case Kind::Write:
        return model::Event::kindName(model::Event::Kind::Write);
    case Kind::Communication:
        return model::Event::kindName(model::Event::Kind::Communication);
    case Kind::Connection:
        return model::Event::kindName(model::Event::Kind::Connection);
    case Kind::ToolChange:
        return model::Event::kindName(model::Event::Kind::ToolChange);
    case Kind::ProfileApply:
        return QStringLiteral("profile apply");
    case Kind::ContextChange:
        return QStringLiteral("context change");
    case Kind::JointWarning:
        return QStringLiteral("joint warning");
    case Kind::Journal:
        return QStringLiteral("journal");
    }
    return {};
}

std::optional<JournalEvent::Kind> JournalEvent::kindFromName(const QString &name) {
    for (const Kind kind : kJournalEventKinds) {
        if (kindName(kind) == name)
            return kind;
    }
    return std::nullopt;
}

QString JournalEvent::severityName(Severity severity) {
    return model::Event::severityName(severity);
}

std::optional<JournalEvent::Severity> JournalEvent::severityFromName(const QString &name) {
    for (const Severity severity : kSeverities) {
        if (severityName(severity) == name)
            return severity;
    }
    return std::nullopt;
}

JournalEvent JournalEvent::fromEventLog(const model::Event &event,
                                        const model::DeviceIdentity &device,
                                        std::optional<int> port) {
    JournalEvent out;
    out.kind = kindOf(event.kind);
    out.severity = event.severity;
    out.device = device;
    out.port = port;
    out.timeMs = event.time.isValid() ? event.time.toMSecsSinceEpoch() : 0;
    out.text = event.text;
    return out;
}

} // namespace tipscope::journal
