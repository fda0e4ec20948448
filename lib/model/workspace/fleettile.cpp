#include "model/workspace/fleettile.h"

#include "model/device/feedermodel.h"
#include "model/device/stationmodel.h"
#include "model/joints/jointtable.h"
#include "model/workspace/workspace.h"

#include <QDateTime>
#include <QLocale>

namespace tipscope::model {

using protocol::Role;

namespace {

qint64 systemClock() {
    return QDateTime::currentMSecsSinceEpoch();
}

// A code of 0 is "no error" in every table; a problem is never shown as less than a warning, so
// a fault the catalog ranks low still stands out among working devices.
void addError(QList<FleetProblem> &problems, std::optional<int> code, Level level,
              const QString &text) {
    if (code && *code != 0)
        problems.append({qMax(Level::Warning, level), text});
}

FleetPortState portState(const PortModel &port) {
    FleetPortState s;
    s.number = port.number();
    s.tip = port.tipTemperature();
    s.setpoint = port.selectedTemperature();
    s.tipText = port.displayText(Role::TipTemperature);
    s.setpointText = port.displayText(Role::Setpoint);
    s.powerText = port.displayText(Role::Power);
    s.toolText = port.toolName();
    const auto status = port.status();
    s.statusText = status ? status->text() : FleetTile::tr("—");
    return s;
}

void addPortProblems(QList<FleetProblem> &problems, const PortModel &port) {
    addError(problems, port.error(), port.errorLevel(),
             FleetTile::tr("Port %1: %2").arg(port.number()).arg(port.errorText()));
    if (const auto alarm = port.alarm(); alarm && alarm->any())
        problems.append({alarm->level(),
                         FleetTile::tr("Port %1 alarm: %2").arg(port.number()).arg(alarm->text())});
}

QString feederText(const FeederModel &feeder) {
    const auto feeding = feeder.isFeeding();
    const QString what = !feeding   ? FleetTile::tr("—")
                         : *feeding ? FleetTile::tr("Feeding")
                                    : FleetTile::tr("Not feeding");
    return FleetTile::tr("%1 · fed %2").arg(what, feeder.displayText(Role::FedLength));
}

// The run of digits at `at` without its leading zeros; `at` moves past it.
QStringView digitRun(const QString &s, qsizetype &at) {
    const qsizetype start = at;
    while (at < s.size() && s.at(at).isDigit())
        ++at;
    qsizetype first = start;
    while (first + 1 < at && s.at(first) == u'0')
        ++first;
    return QStringView(s).mid(first, at - first);
}

// As people count: runs of digits compare by their value ("cell-2" before "cell-10"), the rest
// without regard to case. QCollator's numeric mode would, but not in the C locale.
int compareNames(const QString &a, const QString &b) {
    qsizetype i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (a.at(i).isDigit() && b.at(j).isDigit()) {
            const QStringView na = digitRun(a, i), nb = digitRun(b, j);
            if (na.size() != nb.size())
                return na.size() < nb.size() ? -1 : 1;
            if (const int c = na.compare(nb))
                return c;
            continue;
        }
        if (const int c = QString::compare(a.at(i), b.at(j), Qt::CaseInsensitive))
            return c;
        ++i;
        ++j;
    }
    return int(a.size() - i) - int(b.size() - j);
}

} // namespace

bool operator==(const FleetPortState &a, const FleetPortState &b) {
    return a.number == b.number && a.tip == b.tip && a.setpoint == b.setpoint &&
           a.tipText == b.tipText && a.setpointText == b.setpointText &&
           a.powerText == b.powerText && a.toolText == b.toolText && a.statusText == b.statusText &&
           a.lastJoint == b.lastJoint;
}

bool operator==(const FleetTileState &a, const FleetTileState &b) {
    return a.deviceName == b.deviceName && a.lineName == b.lineName && a.cell == b.cell &&
           a.model == b.model && a.ports == b.ports && a.feederText == b.feederText &&
           a.problems == b.problems && a.lastJoint == b.lastJoint &&
           a.lastJointPort == b.lastJointPort && a.read == b.read && a.lineUp == b.lineUp &&
           a.downSinceMs == b.downSinceMs && a.lineText == b.lineText && a.lineOnly == b.lineOnly;
}

Level FleetTileState::worst() const {
    if (!read && problems.isEmpty())
        return Level::Unknown;
    Level level = lastJoint ? jointLevel(*lastJoint) : Level::Ok;
    for (const FleetProblem &p : problems)
        level = qMax(level, p.level);
    return level;
}

bool FleetTileState::needsAttention() const {
    return !lineUp || worst() >= Level::Warning;
}

int FleetTileState::stateRank() const {
    if (!lineUp)
        return 0;
    switch (worst()) {
    case Level::Error:
        return 1;
    case Level::Warning:
        return 2;
    case Level::Info:
        return 3;
    case Level::Ok:
        return 4;
    case Level::Unknown:
        return 5;
    }
    return 5;
}

bool fleetTileBefore(const FleetTileState &a, const FleetTileState &b, FleetSortKey key) {
    if (key == FleetSortKey::Line) {
        if (const int byLine = compareNames(a.lineName, b.lineName))
            return byLine < 0;
    } else if (key == FleetSortKey::State && a.stateRank() != b.stateRank()) {
        return a.stateRank() < b.stateRank();
    }
    if (const int byName = compareNames(a.deviceName, b.deviceName))
        return byName < 0;
    return compareNames(a.lineName, b.lineName) < 0;
}

FleetTile::FleetTile(const Workspace &workspace, int line, DeviceModel &device, Clock clock,
                     QObject *parent)
    : FleetTileSource(parent)
    , m_workspace(workspace)
    , m_line(line)
    , m_device(&device)
    , m_clock(clock ? std::move(clock) : Clock(systemClock)) {
    if (!device.isLineUp())
        m_downSinceMs = lastReadingMs();
    connect(&device, &DeviceModel::parameterChanged, this, &FleetTile::changed);
    connect(&device, &DeviceModel::temperatureUnitChanged, this, &FleetTile::changed);
    connect(&device, &DeviceModel::lineUpChanged, this, &FleetTile::onLineUpChanged);
    connect(&workspace.session(line)->joints(), &JointWatcher::jointEnded, this,
            &FleetTile::onJoint);
    if (auto *station = qobject_cast<StationModel *>(&device))
        for (const PortModel *port : station->ports())
            if (Parameter *tip = port->parameter(Role::TipTemperature))
                connect(tip, &Parameter::updated, this, &FleetTile::sampleArrived);
}

void FleetTile::onLineUpChanged(bool up) {
    m_downSinceMs = up ? std::nullopt : std::optional<qint64>(m_clock());
    Q_EMIT changed();
}

void FleetTile::onJoint(const JointRecord &joint) {
    if (!m_device || joint.device != m_device->identity())
        return;
    m_portJoints.insert(joint.port, joint.verdict);
    m_lastJoint = joint.verdict;
    m_lastJointPort = joint.port;
    Q_EMIT changed();
}

std::optional<qint64> FleetTile::lastReadingMs() const {
    std::optional<qint64> last;
    for (const Parameter *p : m_device->parameters())
        if (const QDateTime at = p->lastUpdate(); at.isValid())
            last = qMax(last.value_or(0), at.toMSecsSinceEpoch());
    return last;
}

QString FleetTile::downText(std::optional<qint64> sinceMs, qint64 nowMs) {
    if (!sinceMs)
        return tr("Line down");
    const QDateTime since = QDateTime::fromMSecsSinceEpoch(*sinceMs);
    const QLocale locale;
    const QString time = locale.toString(since.time(), QStringLiteral("HH:mm"));
    if (since.date() == QDateTime::fromMSecsSinceEpoch(nowMs).date())
        return tr("Line down since %1").arg(time);
    return tr("Line down since %1 %2")
        .arg(locale.toString(since.date(), QLocale::ShortFormat), time);
}

FleetTileState FleetTile::state() const {
    FleetTileState s;
    const WorkspaceLine &line = m_workspace.line(m_line);
    s.lineName = line.name;
    s.cell = line.cell;
    if (!m_device)
        return s;
    const DeviceModel &device = *m_device;
    s.deviceName = m_workspace.deviceName(m_line, device);
    s.model = device.info().model;
    for (const Parameter *p : device.parameters())
        s.read |= p->value().has_value();
    if (const auto *station = qobject_cast<const StationModel *>(&device)) {
        addError(s.problems, station->stationError(), station->stationErrorLevel(),
                 tr("Station: %1").arg(station->stationErrorText()));
        for (const PortModel *port : station->ports()) {
            FleetPortState ps = portState(*port);
            if (const auto joint = m_portJoints.constFind(port->number());
                joint != m_portJoints.cend())
                ps.lastJoint = *joint;
            s.ports.append(ps);
            addPortProblems(s.problems, *port);
        }
    } else if (const auto *feeder = qobject_cast<const FeederModel *>(&device)) {
        s.feederText = feederText(*feeder);
        addError(s.problems, feeder->errorCode(), feeder->errorLevel(),
                 tr("Feeder: %1").arg(feeder->errorText()));
    }
    std::stable_sort(
        s.problems.begin(), s.problems.end(),
        [](const FleetProblem &a, const FleetProblem &b) { return a.level > b.level; });
    s.lastJoint = m_lastJoint;
    s.lastJointPort = m_lastJointPort;
    s.lineUp = device.isLineUp();
    if (!s.lineUp) {
        s.downSinceMs = m_downSinceMs;
        s.lineText = downText(m_downSinceMs, m_clock());
    }
    return s;
}

} // namespace tipscope::model
