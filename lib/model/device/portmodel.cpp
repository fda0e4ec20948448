#include "portmodel.h"

#include "stationmodel.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct PortModelTr {
    Q_DECLARE_TR_FUNCTIONS(PortModel)
};
} // namespace

PortStatus PortStatus::fromNumber(qint64 v) {
    PortStatus s;
    s.mode = Mode(qBound(qint64(0), v % 10, qint64(3)));
    s.cooling = (v / 10) % 10 == 1;
    s.suction = (v / 100) % 10 == 1;
    s.motor = int((v / 1000) % 10);
    return s;
}

QString PortStatus::modeName(Mode mode) {
    switch (mode) {
    case Mode::Working:
        return PortModelTr::tr("Working");
    case Mode::Stand:
        return PortModelTr::tr("Stand");
    case Mode::Sleep:
        return PortModelTr::tr("Sleep");
    case Mode::Hibernation:
        return PortModelTr::tr("Hibernation");
    }
    return {};
}

QString PortStatus::text() const {
    QStringList parts{modeName(mode)};
    if (cooling)
        parts.append(PortModelTr::tr("Cooling"));
    if (suction)
        parts.append(PortModelTr::tr("Suction"));
    if (motor == 1)
        parts.append(PortModelTr::tr("Motor forward"));
    else if (motor == 2)
        parts.append(PortModelTr::tr("Motor backward"));
    return parts.join(QLatin1String(", "));
}

TemperatureAlarm TemperatureAlarm::fromNumber(qint64 v) {
    return {v % 10 == 1, (v / 10) % 10 == 1};
}

QString TemperatureAlarm::text() const {
    QStringList parts;
    if (high)
        parts.append(PortModelTr::tr("High temperature"));
    if (low)
        parts.append(PortModelTr::tr("Low temperature"));
    return parts.isEmpty() ? PortModelTr::tr("None") : parts.join(QLatin1String(", "));
}

// The station raises an alarm when the tip leaves the band its alarm settings put around the
// selected temperature: what a technician can look at, in the order worth looking.
QString TemperatureAlarm::advice() const {
    QStringList parts;
    if (high)
        parts.append(PortModelTr::tr(
            "the tip went above the high alarm limit: if the selected temperature was just "
            "lowered, wait for the tip to cool; check that the tip suits the tool and the high "
            "alarm limit (Settings, Alarms)"));
    if (low)
        parts.append(PortModelTr::tr(
            "the tip fell below the low alarm limit: the joint may draw more heat than the tip "
            "gives (a larger tip), the tip may be worn or not tinned; check the low alarm limit "
            "(Settings, Alarms)"));
    return parts.join(QLatin1String("; "));
}

PortModel::PortModel(StationModel &station, int port, QObject *parent)
    : QObject(parent)
    , m_station(station)
    , m_port(port) {
    for (Parameter *p : station.parameters())
        if (p->spec().port == port)
            connect(p, &Parameter::valueChanged, this, &PortModel::changed);
}

Parameter *PortModel::parameter(Role role) const {
    return m_station.parameter(role, m_port);
}

QString PortModel::displayText(Role role) const {
    return m_station.displayText(role, m_port);
}

std::optional<qint64> PortModel::tipTemperature() const {
    return m_station.number(Role::TipTemperature, m_port);
}
std::optional<qint64> PortModel::selectedTemperature() const {
    return m_station.number(Role::Setpoint, m_port);
}
std::optional<qint64> PortModel::power() const {
    return m_station.number(Role::Power, m_port);
}

std::optional<PortStatus> PortModel::status() const {
    const auto v = m_station.number(Role::Status, m_port);
    return v ? std::optional<PortStatus>(PortStatus::fromNumber(*v)) : std::nullopt;
}

std::optional<int> PortModel::tool() const {
    const auto v = m_station.number(Role::ConnectedTool, m_port);
    return v ? std::optional<int>(int(*v)) : std::nullopt;
}

QString PortModel::toolName() const {
    const auto t = tool();
    return t ? toolName(*t) : PortModelTr::tr("—");
}

QString PortModel::toolName(int tool) const {
    return m_station.toolName(tool);
}

std::optional<int> PortModel::error() const {
    const auto v = m_station.number(Role::Error, m_port);
    return v ? std::optional<int>(m_station.catalog().canonicalPortError(int(*v))) : std::nullopt;
}

QString PortModel::errorText() const {
    const auto e = error();
    return e ? m_station.catalog().portErrorText(m_station.family(), *e, Wording::Translated)
             : PortModelTr::tr("—");
}

Level PortModel::errorLevel() const {
    return levelOf(m_station.catalog(), m_station.familyInfo().portErrors, error());
}

std::optional<TemperatureAlarm> PortModel::alarm() const {
    const auto v = m_station.number(Role::Alarm, m_port);
    return v ? std::optional<TemperatureAlarm>(TemperatureAlarm::fromNumber(*v)) : std::nullopt;
}

int PortModel::alarmFlags() const {
    return int(m_station.number(Role::Alarm, m_port).value_or(0));
}

QList<int> PortModel::toolOrder() const {
    QList<int> order = m_station.familyInfo().tools;
    if (const auto t = tool(); t && order.contains(*t)) {
        order.removeAll(*t);
        order.prepend(*t);
    }
    return order;
}

QList<Parameter *> PortModel::settings() const {
    return m_station.parameters(Group::Port, m_port);
}

QList<Parameter *> PortModel::toolSettings(int tool) const {
    return m_station.parameters(Group::Tool, m_port, tool);
}

QList<Parameter *> PortModel::alarmSettings() const {
    return m_station.parameters(Group::Alarm, m_port);
}

QList<Parameter *> PortModel::counters() const {
    return m_station.parameters(Group::Counter, m_port);
}

QList<Parameter *> PortModel::parameters(std::initializer_list<Role> roles) const {
    QList<Parameter *> out;
    for (Role role : roles)
        if (Parameter *p = parameter(role))
            out.append(p);
    return out;
}

QList<Parameter *> PortModel::liveParameters() const {
    return parameters({Role::TipTemperature, Role::Power, Role::Status, Role::Setpoint});
}

QList<Parameter *> PortModel::statusParameters() const {
    return parameters({Role::ConnectedTool, Role::Error, Role::Alarm, Role::TimeToNextMode,
                       Role::TransistorTemperature});
}

QString PortModel::write(Role role, qint64 value) {
    Parameter *p = parameter(role);
    if (!p)
        return PortModelTr::tr("this port has no %1 command").arg(m_station.commandName(role));
    const QString why = p->setEdit(value);
    if (why.isEmpty())
        p->apply();
    return why;
}

QString PortModel::setMode(int writeValue) {
    return write(Role::Status, writeValue);
}

QString PortModel::setSelectedTemperature(qint64 celsius) {
    return write(Role::Setpoint, celsius);
}

} // namespace tipscope::model
