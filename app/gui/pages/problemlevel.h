// How bad something is, as the Errors page shows it: a word, an icon and a tint, ranked so the
// worst of several can be taken with qMax. Catalog error tables and EventLog severities both map
// onto it.
#pragma once

#include "model/eventlog.h"

#include <QIcon>
#include <QVariant>

namespace tipscope::gui {

// In the order a reader ranks it; Unknown = not read yet.
enum class Level { Unknown, Ok, Info, Warning, Error };

// From a catalog error table's severity ("ok", "info", "warning", anything else is an error).
[[nodiscard]] Level levelOf(const QString &catalogSeverity);
[[nodiscard]] Level levelOf(model::Event::Severity severity);
[[nodiscard]] QString levelName(Level level);
[[nodiscard]] QIcon levelIcon(Level level);
// A background brush colour, or an empty QVariant for levels that are not tinted.
[[nodiscard]] QVariant levelTint(Level level);

} // namespace tipscope::gui
