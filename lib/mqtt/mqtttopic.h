// MQTT topic names and subscription filters as TipScope builds and routes them.
//
// sanitizeTopicLevel() makes one level of a published topic from a name people chose (a site,
// a line, a device): lower-cased, and every character outside [a-z0-9_-] (one per Unicode code
// point, so `/`, `+`, `#`, spaces and umlauts too) becomes `_`. An empty name becomes `_`, so no
// level is ever empty. topicMatchesFilter() is the broker's own rule for `+` (one level) and `#`
// (this level and all below), for routing received messages to views; like brokers, it does not
// let a filter that starts with a wildcard match a topic that starts with `$`.
#pragma once

#include <QString>

namespace tipscope::mqtt {

[[nodiscard]] QString sanitizeTopicLevel(const QString &name);

// A name one may publish to: not empty, no wildcards, no NUL, at most 65535 bytes in UTF-8.
[[nodiscard]] bool isValidTopicName(const QString &topic);
// A filter one may subscribe to: `+` alone in its level, `#` alone in the last level.
[[nodiscard]] bool isValidTopicFilter(const QString &filter);

// False when either argument is invalid.
[[nodiscard]] bool topicMatchesFilter(const QString &topic, const QString &filter);

} // namespace tipscope::mqtt
