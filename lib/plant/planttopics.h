// PlantTopics: where TipScope publishes a device on MQTT, docs/mqtt.md's interface (version 1).
//
// A device's root is `tipscope/v1/<site>/<line>/<device>`: `<device>` is the name the workspace
// gives it, or `<address>-<family>` ("01-dme", "10-sfr"), or `--<family>` ("--ddr") for a device
// that answers without addresses. Every level goes through sanitizeTopicLevel() (lower case,
// anything outside [a-z0-9_-] becomes `_`). Records about no device in particular (a context
// change, the journal's own reports) go under the agent's root, `tipscope/v1/<site>/_agent/<id>`;
// a line that is itself called `_agent` is published as `__agent`, so the two never mix.
//
// parseDeviceTopic() is the way back, for views that subscribe to `tipscope/v1/#`: the site, line
// and device levels of a topic under a device's root, and what follows them.
#pragma once

#include <QString>
#include <optional>

namespace tipscope::plant {

inline constexpr char kTopicPrefix[] = "tipscope/v1";

// The device level: `name` when it is not empty, else from the address and family.
[[nodiscard]] QString deviceLevel(const QString &name, std::optional<int> address,
                                  const QString &family);
[[nodiscard]] QString deviceRoot(const QString &site, const QString &line, const QString &device);
[[nodiscard]] QString agentRoot(const QString &site, const QString &agentId);

// Where a device is published: what its live messages, its presence and its journaled records
// all go by.
struct DevicePlace {
    QString line;   // the workspace line's name
    QString name;   // the name the workspace gives the device, or empty
    QString root;   // its topic root
    QString client; // the presence client's id
};
// The place of the device at `address` of `family` on the workspace line `line`, named `name`
// there (or not), published by the agent `agentId` at `site`.
[[nodiscard]] DevicePlace devicePlace(const QString &site, const QString &agentId,
                                      const QString &line, const QString &name,
                                      std::optional<int> address, const QString &family);
// The agent's own, for records about no device in particular: no line, no presence client.
[[nodiscard]] DevicePlace agentPlace(const QString &site, const QString &agentId);

struct DeviceTopic {
    QString site;
    QString line;
    QString device;
    QString leaf; // "status", "port/1/live", ...
};
// None for a topic outside `tipscope/v1/<site>/<line>/<device>/...` or under an agent's root.
[[nodiscard]] std::optional<DeviceTopic> parseDeviceTopic(const QString &topic);

} // namespace tipscope::plant
