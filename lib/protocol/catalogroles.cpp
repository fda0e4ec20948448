#include "catalogroles.h"

#include <QMap>

namespace tipscope::protocol {

namespace {

const QMap<Role, QString> &roleNames() {
    static const QMap<Role, QString> names = {
        {Role::TipTemperature, QStringLiteral("tipTemperature")},
        {Role::Setpoint, QStringLiteral("setpoint")},
        {Role::Power, QStringLiteral("power")},
        {Role::Status, QStringLiteral("status")},
        {Role::ConnectedTool, QStringLiteral("connectedTool")},
        {Role::TimeToNextMode, QStringLiteral("timeToNextMode")},
        {Role::TransistorTemperature, QStringLiteral("transistorTemperature")},
        {Role::TransformerTemperature, QStringLiteral("transformerTemperature")},
        {Role::Fuse, QStringLiteral("fuse")},
        {Role::MinTemperature, QStringLiteral("minTemperature")},
        {Role::MaxTemperature, QStringLiteral("maxTemperature")},
        {Role::PowerLimit, QStringLiteral("powerLimit")},
        {Role::Error, QStringLiteral("error")},
        {Role::Alarm, QStringLiteral("alarm")},
        {Role::HighAlarm, QStringLiteral("highAlarm")},
        {Role::LowAlarm, QStringLiteral("lowAlarm")},
        {Role::HighAlarmDelay, QStringLiteral("highAlarmDelay")},
        {Role::LowAlarmDelay, QStringLiteral("lowAlarmDelay")},
        {Role::Feeding, QStringLiteral("feeding")},
        {Role::FedLength, QStringLiteral("fedLength")},
        {Role::FeedSpeed, QStringLiteral("feedSpeed")},
        {Role::FeedLength, QStringLiteral("feedLength")},
        {Role::DispensedLength, QStringLiteral("dispensedLength")},
        {Role::DispensedCycles, QStringLiteral("dispensedCycles")},
        {Role::ModelName, QStringLiteral("modelName")},
        {Role::SoftwareVersion, QStringLiteral("softwareVersion")},
        {Role::SaveToMemory, QStringLiteral("saveToMemory")},
        {Role::FactoryReset, QStringLiteral("factoryReset")},
        {Role::Restart, QStringLiteral("restart")},
        {Role::SetAddress, QStringLiteral("setAddress")},
        {Role::IgnoreFuseError, QStringLiteral("ignoreFuseError")},
        {Role::Start, QStringLiteral("start")},
        {Role::Stop, QStringLiteral("stop")},
        {Role::Loading, QStringLiteral("loading")},
        {Role::ResetError, QStringLiteral("resetError")},
    };
    return names;
}

const QMap<Group, QString> &groupNames() {
    static const QMap<Group, QString> names = {
        {Group::Live, QStringLiteral("live")},
        {Group::Port, QStringLiteral("port")},
        {Group::Tool, QStringLiteral("tool")},
        {Group::Alarm, QStringLiteral("alarm")},
        {Group::Station, QStringLiteral("station")},
        {Group::Errors, QStringLiteral("errors")},
        {Group::Counter, QStringLiteral("counter")},
        {Group::Dispensing, QStringLiteral("dispensing")},
        {Group::Feeder, QStringLiteral("feeder")},
        {Group::Identity, QStringLiteral("identity")},
        {Group::Actions, QStringLiteral("actions")},
    };
    return names;
}

template <typename T>
std::optional<T> fromName(const QMap<T, QString> &names, const QString &name) {
    for (auto it = names.begin(); it != names.end(); ++it)
        if (it.value() == name)
            return it.key();
    return std::nullopt;
}

} // namespace

QString roleName(Role role) {
    return roleNames().value(role);
}

QString groupName(Group group) {
    return groupNames().value(group);
}

std::optional<Role> roleFromName(const QString &name) {
    return fromName(roleNames(), name);
}

std::optional<Group> groupFromName(const QString &name) {
    return fromName(groupNames(), name);
}

} // namespace tipscope::protocol
