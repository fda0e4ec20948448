#include "stationstate.h"

#include "model/device/stationmodel.h"

#include <utility>

namespace tipscope::cfx {

namespace {

using Mode = model::PortStatus::Mode;

StationCondition conditionOfMode(Mode mode) {
    switch (mode) {
    case Mode::Working:
        return StationCondition::Working;
    case Mode::Stand:
        return StationCondition::InStand;
    case Mode::Sleep:
        return StationCondition::Sleep;
    case Mode::Hibernation:
        break;
    }
    return StationCondition::Hibernation;
}

} // namespace

std::optional<StationCondition> conditionOf(const model::StationModel &station) {
    // StationCondition lists the port conditions from the most to the least active.
    std::optional<StationCondition> mostActive;
    bool error = station.stationErrorLevel() == model::Level::Error;
    for (const model::PortModel *port : station.ports()) {
        error = error || port->errorLevel() == model::Level::Error;
        if (const auto status = port->status()) {
            const StationCondition condition = conditionOfMode(status->mode);
            if (!mostActive || condition < *mostActive)
                mostActive = condition;
        }
    }
    if (!mostActive)
        return std::nullopt; // nothing read yet
    if (!station.isLineUp())
        return StationCondition::LinkLost;
    if (error)
        return StationCondition::Error;
    return mostActive;
}

StationStateWatcher::StationStateWatcher(model::StationModel &station, QObject *parent)
    : QObject(parent)
    , m_station(&station) {
    for (model::PortModel *port : station.ports())
        connect(port, &model::PortModel::changed, this, &StationStateWatcher::update);
    connect(&station, &model::DeviceModel::parameterChanged, this, &StationStateWatcher::update);
    connect(&station, &model::DeviceModel::lineUpChanged, this, &StationStateWatcher::update);
    m_condition = conditionOf(station);
}

void StationStateWatcher::update() {
    if (!m_station)
        return;
    const std::optional<StationCondition> now = conditionOf(*m_station);
    if (!now || now == m_condition)
        return;
    const std::optional<StationCondition> before = std::exchange(m_condition, now);
    if (!before)
        return; // the first reading: when that condition began is not known
    const std::optional<qint64> lasted =
        m_since.isValid() ? std::optional<qint64>(m_since.elapsed()) : std::nullopt;
    m_since.start();
    Q_EMIT changed(*before, lasted, *now);
}

} // namespace tipscope::cfx
