// The catalog's words for what a command is for (Role) and where it belongs (Group), so that
// models, pages and later front ends find values by meaning rather than by spelling a code.
//
// A Role names one quantity or action of a device, independent of the family's code for it:
// the tip temperature is TTx on every station, the error is SER for the station, PEx for each
// port and ECV for the feeder. Within a family a role is held by at most one command per port
// (0: the device itself) among the values and at most one among the actions, so
// (role, port) finds exactly one value; tst_catalog checks this. A Group says which list a
// command is shown in (station settings, a port's alarms, counters, ...); a new catalog entry
// with a known group reaches its page without code. Both are spelled in commands.json by the
// names roleName() and groupName() give; an unknown name makes the catalog fail to load.
#pragma once

#include <QString>
#include <optional>

namespace tipscope::protocol {

enum class Role {
    None,
    // A port's live values and state.
    TipTemperature,
    Setpoint, // the selected temperature
    Power,
    Status,
    ConnectedTool,
    TimeToNextMode,
    TransistorTemperature,
    // The station's own values and limits.
    TransformerTemperature,
    Fuse,
    MinTemperature,
    MaxTemperature,
    PowerLimit,
    // Errors and alarms (the station's, each port's, the feeder's).
    Error,
    Alarm,
    HighAlarm,
    LowAlarm,
    HighAlarmDelay,
    LowAlarmDelay,
    // Wire feed: the SFR feeder and the ALE's built-in dispensing.
    Feeding,
    FedLength,
    FeedSpeed,
    FeedLength,
    DispensedLength,
    DispensedCycles,
    // Identity.
    ModelName,
    SoftwareVersion,
    // Actions.
    SaveToMemory,
    FactoryReset,
    Restart,
    SetAddress,
    IgnoreFuseError,
    Start,
    Stop,
    Loading,
    ResetError,
};

enum class Group {
    Live,       // a port's live values
    Port,       // a port's settings
    Tool,       // per-tool settings of a port
    Alarm,      // a port's temperature alarm settings
    Station,    // the station's own settings
    Errors,     // errors, alarms, the fuse
    Counter,    // usage counters
    Dispensing, // the ALE's wire feed
    Feeder,     // the SFR feeder
    Identity,   // model name, software version
    Actions,    // save, reset, restart, address
};

// The names used in commands.json ("tipTemperature", "counter"); empty for Role::None.
[[nodiscard]] QString roleName(Role role);
[[nodiscard]] QString groupName(Group group);
[[nodiscard]] std::optional<Role> roleFromName(const QString &name);
[[nodiscard]] std::optional<Group> groupFromName(const QString &name);

} // namespace tipscope::protocol
