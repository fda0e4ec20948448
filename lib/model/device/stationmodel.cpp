#include "stationmodel.h"

#include "model/events/eventlog.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct StationModelTr {
    Q_DECLARE_TR_FUNCTIONS(StationModel)
};

// A change's wire numbers beside its words, for programs: the words are translated, and the
// status number holds flags besides the status (docs/mqtt.md, the event's details).
QJsonObject wireChange(qint64 from, qint64 to) {
    return {{QStringLiteral("from"), from}, {QStringLiteral("to"), to}};
}

Event::Severity severityOf(const Catalog &catalog, const QString &tableName, int code) {
    const QString s = catalog.severity(tableName, code);
    if (s == QLatin1String("error"))
        return Event::Severity::Error;
    if (s == QLatin1String("warning"))
        return Event::Severity::Warning;
    return Event::Severity::Info;
}
} // namespace

StationModel::StationModel(link::RequestQueue &queue, const link::DeviceInfo &info, QObject *parent)
    : StationModel(queue, info, Catalog::builtin(), parent) {}

StationModel::StationModel(link::RequestQueue &queue, const link::DeviceInfo &info,
                           const Catalog &catalog, QObject *parent)
    : DeviceModel(queue, info, catalog, parent) {
    for (int p = 1; p <= familyInfo().ports; ++p)
        m_ports.append(new PortModel(*this, p, this));
}

QList<Parameter *> StationModel::stationSettings() const {
    return parameters(Group::Station, 0);
}

QList<Parameter *> StationModel::dispensingSettings() const {
    return parameters(Group::Dispensing);
}

QList<Parameter *> StationModel::counters() const {
    return parameters(Group::Counter, 0);
}

std::optional<int> StationModel::stationError() const {
    const auto v = number(Role::Error);
    return v ? std::optional<int>(int(*v)) : std::nullopt;
}

QString StationModel::stationErrorText() const {
    const auto e = stationError();
    return e ? catalog().stationErrorText(family(), *e, Wording::Translated)
             : StationModelTr::tr("—");
}

Level StationModel::stationErrorLevel() const {
    return levelOf(catalog(), familyInfo().stationErrors, stationError());
}

std::optional<qint64> StationModel::transformerTemperature() const {
    return number(Role::TransformerTemperature);
}

std::optional<bool> StationModel::fusePresent() const {
    const auto v = number(Role::Fuse);
    return v ? std::optional<bool>(*v == 1) : std::nullopt;
}

QString StationModel::triggerAction(Role role, Confirmation c, qint64 argument) {
    Action *a = action(role);
    if (!a)
        return StationModelTr::tr("%1 does not support %2").arg(displayName(), commandName(role));
    return a->trigger(c, argument);
}

QString StationModel::saveToMemory() {
    Action *save = action(Role::SaveToMemory);
    if (!save)
        return StationModelTr::tr("%1 cannot save to memory").arg(displayName());
    connect(
        save, &Action::finished, this,
        [this, code = QString::fromLatin1(save->code())](bool ok) {
            if (!ok)
                return;
            for (Parameter *p : parameters())
                if (p->meta().savedBy == code)
                    p->markSaved();
        },
        Qt::SingleShotConnection);
    return save->trigger();
}

void StationModel::onParameterChanged(Parameter *p) {
    const Role role = p->meta().role;
    if (role == Role::Error || role == Role::Alarm || role == Role::Status ||
        role == Role::ConnectedTool)
        logChange(p, p->spec().port);
}

void StationModel::logChange(Parameter *p, int port) {
    EventLog *log = eventLog();
    const auto v = p->number();
    if (!log || !v)
        return;
    const QByteArray code = p->code();
    const bool first = !m_lastLogged.contains(code);
    const qint64 before = m_lastLogged.value(code, 0);
    m_lastLogged.insert(code, *v);
    if (before == *v && !first)
        return;
    const Role role = p->meta().role;
    // Stamped at the instant the station showed it, as its tip's samples are.
    const double age = p->reportedAgeMs();
    if (role == Role::ConnectedTool) {
        if (!first)
            logEvent(Event::Kind::ToolChange, Event::Severity::Info, port,
                     StationModelTr::tr("%1 → %2").arg(toolName(int(before)), toolName(int(*v))),
                     wireChange(before, *v), age);
    } else if (role == Role::Status) {
        if (!first)
            logEvent(Event::Kind::Status, Event::Severity::Info, port,
                     StationModelTr::tr("%1 → %2").arg(PortStatus::fromNumber(before).text(),
                                                       PortStatus::fromNumber(*v).text()),
                     wireChange(before, *v), age);
    } else if (role == Role::Alarm) {
        if (*v != 0)
            logEvent(Event::Kind::Alarm, Event::Severity::Warning, port, p->displayText(), {}, age);
    } else {
        const bool isStation = port == 0;
        const QString table = isStation ? familyInfo().stationErrors : familyInfo().portErrors;
        const int code = isStation ? int(*v) : catalog().canonicalPortError(int(*v));
        if (code != 0)
            logEvent(isStation ? Event::Kind::StationError : Event::Kind::PortError,
                     severityOf(catalog(), table, code), port, p->displayText(), {}, age);
        else if (!first)
            logEvent(isStation ? Event::Kind::StationError : Event::Kind::PortError,
                     Event::Severity::Info, port, StationModelTr::tr("error cleared"), {}, age);
    }
}

} // namespace tipscope::model
