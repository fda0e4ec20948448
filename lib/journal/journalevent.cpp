#include "journalevent.h"

namespace tipscope::journal {

namespace {

using Kind = JournalEvent::Kind;
using Severity = JournalEvent::Severity;

constexpr Severity kSeverities[] = {Severity::Info, Severity::Warning, Severity::Error};

} // namespace

QString JournalEvent::kindName(Kind kind) {
    return model::Event::kindName(kind);
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
    out.kind = event.kind;
    out.severity = event.severity;
    out.device = device;
    out.port = port;
    out.timeMs = event.time.isValid() ? event.time.toMSecsSinceEpoch() : 0;
    out.text = event.text;
    out.details = event.details;
    return out;
}

} // namespace tipscope::journal
