#include "devicemodel.h"

#include "model/events/eventlog.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {
struct DeviceModelTr {
    Q_DECLARE_TR_FUNCTIONS(DeviceModel)
};
} // namespace

DeviceModel::DeviceModel(RequestQueue &queue, const DeviceInfo &info, QObject *parent)
    : DeviceModel(queue, info, Catalog::builtin(), parent) {}

DeviceModel::DeviceModel(RequestQueue &queue, const DeviceInfo &info, const Catalog &catalog,
                         QObject *parent)
    : QObject(parent)
    , m_queue(queue)
    , m_info(info)
    , m_catalog(catalog)
    , m_lineUp(queue.isOpen()) {
    const Catalog &cat = m_catalog;
    QMap<QByteArray, std::optional<ResolvedCommand>> reads, writes;
    QList<QByteArray> order;
    for (const ResolvedCommand &r : cat.expand(info.family, Direction::Read)) {
        reads[r.code] = r;
        order.append(r.code);
    }
    for (const ResolvedCommand &w : cat.expand(info.family, Direction::Write)) {
        if (w.spec->isAction()) {
            auto *a = new Action(*this, w, this);
            m_actions.append(a);
            m_actionByCode.insert(w.code, a);
            if (w.spec->role != Role::None)
                m_actionByRole.insert(w.spec->role, a);
            continue;
        }
        writes[w.code] = w;
        if (!order.contains(w.code))
            order.append(w.code);
    }
    for (const QByteArray &code : order) {
        auto *p = new Parameter(*this, reads.value(code), writes.value(code), this);
        m_parameters.append(p);
        m_byCode.insert(code, p);
    }
    indexByRole();
    for (Parameter *p : m_parameters) {
        const CommandSpec &s = p->meta();
        if (!s.limitMin.isEmpty() || !s.limitMax.isEmpty())
            p->setLimitParameters(parameter(s.limitMin.toLatin1()),
                                  parameter(s.limitMax.toLatin1()));
    }
    connect(this, &DeviceModel::parameterChanged, this,
            [this](Parameter *p) { onParameterChanged(p); });
}

const FamilyInfo &DeviceModel::familyInfo() const {
    return *m_catalog.family(m_info.family);
}

QString DeviceModel::displayName() const {
    return m_info.address ? DeviceModelTr::tr("%1 at %2").arg(m_info.model, m_info.addressText())
                          : DeviceModelTr::tr("%1 (no address)").arg(m_info.model);
}

QString DeviceModel::sourceName(int port) const {
    return port > 0 ? DeviceModelTr::tr("%1, port %2").arg(displayName()).arg(port) : displayName();
}

Parameter *DeviceModel::parameter(const QByteArray &code) const {
    return m_byCode.value(code);
}

Action *DeviceModel::action(const QByteArray &code) const {
    return m_actionByCode.value(code);
}

void DeviceModel::indexByRole() {
    int roles = 0;
    for (const Parameter *p : std::as_const(m_parameters)) {
        roles = qMax(roles, int(p->meta().role) + 1);
        m_rolePorts = qMax(m_rolePorts, p->spec().port + 1);
    }
    m_byRole.assign(size_t(roles) * size_t(m_rolePorts), nullptr);
    for (Parameter *p : std::as_const(m_parameters))
        if (p->meta().role != Role::None && p->spec().port >= 0)
            m_byRole[size_t(int(p->meta().role) * m_rolePorts + p->spec().port)] = p;
}

Parameter *DeviceModel::parameter(Role role, int port) const {
    const size_t at = size_t(int(role) * m_rolePorts + port);
    return port >= 0 && port < m_rolePorts && at < m_byRole.size() ? m_byRole[at] : nullptr;
}

Action *DeviceModel::action(Role role) const {
    return m_actionByRole.value(role);
}

std::optional<qint64> DeviceModel::number(Role role, int port) const {
    const Parameter *p = parameter(role, port);
    return p ? p->number() : std::nullopt;
}

QString DeviceModel::errorAdvice(int port, Wording wording) const {
    const Parameter *p = parameter(Role::Error, port);
    const auto code = p ? p->number() : std::nullopt;
    return code ? catalog().errorAdvice(p->spec(), int(*code), wording) : QString();
}

QString DeviceModel::displayText(Role role, int port) const {
    const Parameter *p = parameter(role, port);
    return p ? p->displayText() : DeviceModelTr::tr("—");
}

QList<Parameter *> DeviceModel::parameters(Group group) const {
    QList<Parameter *> out;
    for (Parameter *p : m_parameters)
        if (p->meta().group == group)
            out.append(p);
    return out;
}

QList<Parameter *> DeviceModel::parameters(Group group, int port, int tool) const {
    QList<Parameter *> out;
    for (Parameter *p : m_parameters)
        if (p->meta().group == group && p->spec().port == port && p->spec().tool == tool)
            out.append(p);
    return out;
}

QString toolName(const Catalog &catalog, const QString &family, int tool, Wording wording) {
    const QMap<int, QString> tools = catalog.table(QStringLiteral("$toolTable"), family);
    if (tools.contains(tool))
        return catalogText(tools.value(tool), wording);
    return wording == Wording::Catalog ? QStringLiteral("tool %1").arg(tool)
                                       : DeviceModelTr::tr("tool %1").arg(tool);
}

QString qualifiedName(const Catalog &catalog, const ResolvedCommand &cmd, Wording wording) {
    const bool english = wording == Wording::Catalog;
    const QString name = catalogText(cmd.spec->name, wording);
    const int port = cmd.port;
    const QString tool =
        cmd.tool >= 0 ? toolName(catalog, cmd.family, cmd.tool, wording) : QString();
    if (port > 0 && !tool.isEmpty())
        return english ? QStringLiteral("%1, %2, port %3").arg(name, tool).arg(port)
                       : DeviceModelTr::tr("%1, %2, port %3").arg(name, tool).arg(port);
    if (port > 0)
        return english ? QStringLiteral("%1, port %2").arg(name).arg(port)
                       : DeviceModelTr::tr("%1, port %2").arg(name).arg(port);
    if (!tool.isEmpty())
        return english ? QStringLiteral("%1, %2").arg(name, tool)
                       : DeviceModelTr::tr("%1, %2").arg(name, tool);
    return name;
}

QString DeviceModel::toolName(int tool, Wording wording) const {
    return model::toolName(m_catalog, family(), tool, wording);
}

QString DeviceModel::qualifiedLabel(const Parameter &p, Wording wording) const {
    return qualifiedName(m_catalog, p.spec(), wording);
}

QString DeviceModel::commandName(Role role) const {
    const CommandSpec *spec = m_catalog.command(role);
    return spec ? spec->pattern : roleName(role);
}

void DeviceModel::setTemperatureUnit(TemperatureUnit unit) {
    if (unit == m_unit)
        return;
    m_unit = unit;
    Q_EMIT temperatureUnitChanged();
}

void DeviceModel::setWritesBlocked(bool blocked) {
    if (blocked == m_writesBlocked)
        return;
    m_writesBlocked = blocked;
    Q_EMIT writesBlockedChanged(blocked);
}

void DeviceModel::setLineUp(bool up) {
    if (up == m_lineUp)
        return;
    m_lineUp = up;
    if (up)
        for (Parameter *p : std::as_const(m_parameters))
            p->lineRestored();
    Q_EMIT lineUpChanged(up);
}

QString DeviceModel::writesUnavailableReason() const {
    if (m_writesBlocked)
        return DeviceModelTr::tr("Monitor-only mode is on: nothing is written.");
    if (!m_lineUp)
        return DeviceModelTr::tr("Not connected: nothing can be sent until the line is back.");
    return {};
}

void DeviceModel::refreshAll(Priority priority) {
    for (Parameter *p : m_parameters)
        if (p->isReadable())
            p->refresh(priority);
}

void DeviceModel::logCommunication(const QString &what, const QString &reason) {
    logEvent(Event::Kind::Communication, Event::Severity::Warning, 0,
             m_queue.isOpen() ? DeviceModelTr::tr("%1: %2").arg(what, reason) : reason);
}

void DeviceModel::logWrite(int port, const QString &what, const QJsonObject &details) {
    logEvent(Event::Kind::Write, Event::Severity::Info, port, what, details);
}

void DeviceModel::logEvent(Event::Kind kind, Event::Severity severity, int port,
                           const QString &text, const QJsonObject &details, double ageMs) {
    if (!m_log)
        return;
    Event e({}, kind, severity, sourceName(port), text);
    e.device = identity();
    e.port = port;
    e.details = details;
    m_log->append(std::move(e), ageMs);
}

DeviceIdentity DeviceModel::identity() const {
    return {m_lineName, m_info.address, m_info.model, m_info.softwareVersion};
}

} // namespace tipscope::model
