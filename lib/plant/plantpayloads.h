// PlantPayloads: the JSON objects TipScope publishes (docs/mqtt.md, version 1), built from the
// models and the journal's records. Plain functions of their inputs, so a test can hold each
// payload against the document.
//
// Every payload carries "ts" (UTC, ISO 8601 with milliseconds), and numbers carry their unit in
// their field's name (tip_c, power_pct, fed_mm). Texts that programs compare (statuses, levels,
// kinds, tool and error names) are the catalog's English, whatever language the publishing
// program shows; a value not read yet is null, never a guess.
#pragma once

#include "journal/journaltypes.h"

#include <QJsonArray>
#include <QJsonObject>

namespace tipscope::model {
class DeviceModel;
class FeederModel;
class PortModel;
} // namespace tipscope::model

namespace tipscope::plant {

// Who publishes: the agent's name and version, for status.
struct Publisher {
    QString agent;
    QString version;
};

[[nodiscard]] QJsonObject statusPayload(bool online, const Publisher &publisher, qint64 nowMs,
                                        bool lineUp = true);
// Model, family, software, address, the line and device names, and each port's connected tool.
[[nodiscard]] QJsonObject infoPayload(const model::DeviceModel &device, const QString &line,
                                      const QString &deviceName, qint64 nowMs);
// One port's tip, setpoint, power, status and tool; "ts" is when the tip was read.
[[nodiscard]] QJsonObject portLivePayload(const model::PortModel &port, qint64 readMs);
[[nodiscard]] QJsonObject feederLivePayload(const model::FeederModel &feeder, qint64 readMs);
// Every counter the device has, the value under its unit's name ("h", "count", "m").
[[nodiscard]] QJsonObject countersPayload(const model::DeviceModel &device, qint64 nowMs);
// The errors and alarms in force; "alarms" is an empty list when there is none.
[[nodiscard]] QJsonArray activeAlarms(const model::DeviceModel &device);
[[nodiscard]] QJsonObject alarmsPayload(const QJsonArray &alarms, qint64 nowMs);
[[nodiscard]] QJsonObject eventPayload(const journal::StoredEvent &event);

} // namespace tipscope::plant
