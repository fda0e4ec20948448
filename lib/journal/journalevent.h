// JournalEvent: one thing that happened, as the journal keeps it for audit: station, port and
// feeder errors, alarms, status and tool changes, setting writes with their read-back, profile
// applies, joint warnings, communication errors, connects and disconnects, as a device's event
// log has them (model::Event::Kind is the one vocabulary), plus what only the journal has:
// context changes and its own reports (records it could not store). A plain value.
//
// The time is milliseconds since the epoch (UTC). The device is empty for an event about no
// device in particular; the port is empty for an event about a whole device. `details` holds
// what a program needs beyond the text: a write's code, value and read-back result, a profile
// apply's hash and changes, a context change's old and new context. Kinds and severities have
// stable English names for files and databases (kindName(), severityName()).
#pragma once

#include "model/context/deviceidentity.h"
#include "model/events/eventlog.h"

#include <QJsonObject>
#include <QString>
#include <optional>

namespace tipscope::journal {

struct JournalEvent {
    // The event log's vocabulary, one from the wire to the screen and the journal.
    using Kind = model::Event::Kind;
    using Severity = model::Event::Severity;

    Kind kind = Kind::Status;
    Severity severity = Severity::Info;
    model::DeviceIdentity device;
    std::optional<int> port;
    qint64 timeMs = 0;
    QString text;
    QJsonObject details;

    [[nodiscard]] static QString kindName(Kind kind);
    [[nodiscard]] static std::optional<Kind> kindFromName(const QString &name);
    [[nodiscard]] static QString severityName(Severity severity);
    [[nodiscard]] static std::optional<Severity> severityFromName(const QString &name);
    // The journal's copy of an EventLog entry about `device` (and `port`, if it is about one).
    [[nodiscard]] static JournalEvent fromEventLog(const model::Event &event,
                                                   const model::DeviceIdentity &device,
                                                   std::optional<int> port = std::nullopt);

    friend bool operator==(const JournalEvent &a, const JournalEvent &b) {
        return a.kind == b.kind && a.severity == b.severity && a.device == b.device &&
               a.port == b.port && a.timeMs == b.timeMs && a.text == b.text &&
               a.details == b.details;
    }
    friend bool operator!=(const JournalEvent &a, const JournalEvent &b) { return !(a == b); }
};

inline constexpr JournalEvent::Kind kJournalEventKinds[] = {
    JournalEvent::Kind::StationError,  JournalEvent::Kind::PortError,
    JournalEvent::Kind::FeederError,   JournalEvent::Kind::Alarm,
    JournalEvent::Kind::Status,        JournalEvent::Kind::Write,
    JournalEvent::Kind::Communication, JournalEvent::Kind::Connection,
    JournalEvent::Kind::ToolChange,    JournalEvent::Kind::ProfileApply,
    JournalEvent::Kind::ContextChange, JournalEvent::Kind::JointWarning,
    JournalEvent::Kind::Journal};

} // namespace tipscope::journal
