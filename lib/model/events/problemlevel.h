// How bad something is, ranked so that the worst of several can be taken with qMax: the catalog's
// error tables (through their severities) and the EventLog's severities both map onto it. Front
// ends show it in their own way (the Errors page as a word, an icon and a tint).
#pragma once

#include "eventlog.h"

#include <QString>
#include <optional>

namespace tipscope::protocol {
class Catalog;
}

namespace tipscope::model {

// In the order a reader ranks it; Unknown = not read yet.
enum class Level { Unknown, Ok, Info, Warning, Error };

// From a catalog error table's severity ("ok", "info", "warning", anything else is an error).
[[nodiscard]] Level levelOf(const QString &catalogSeverity);
[[nodiscard]] Level levelOf(Event::Severity severity);
// The level of an error code in a catalog table (Catalog::severity()); Unknown when not read.
[[nodiscard]] Level levelOf(const protocol::Catalog &catalog, const QString &tableName,
                            std::optional<int> code);
[[nodiscard]] QString levelName(Level level);

} // namespace tipscope::model
