// What a value of a device is called where it appears out of its group: in the event history,
// the support report, the profile dialog's rows. A per-tool or per-port value carries its tool
// and port ("Sleep delay, T245/T470 (TR245/TR470), port 1"), so that the eight tools' "Temperature
// adjust" of four ports read as 32 different lines, not 32 identical ones. Inside its own group
// (a port's card, a tool's box) the catalog's name alone reads better: Parameter::label().
#pragma once

#include "protocol/catalog.h"

#include <QString>

namespace tipscope::model {

class Parameter;

// How much of the place to say: all of it, or the tool only where the port is said beside it
// (the history's Source column names the port).
enum class NameParts { ToolAndPort, ToolOnly };

// "Sleep delay, T245/T470 (TR245/TR470), port 1", "Selected temperature, port 2", "Maximum
// temperature"; in the catalog's English for Wording::Catalog.
[[nodiscard]] QString settingName(const protocol::ResolvedCommand &command,
                                  const protocol::Catalog &catalog,
                                  NameParts parts = NameParts::ToolAndPort,
                                  protocol::Wording wording = protocol::Wording::Translated);
[[nodiscard]] QString settingName(const Parameter &parameter,
                                  NameParts parts = NameParts::ToolAndPort,
                                  protocol::Wording wording = protocol::Wording::Translated);

} // namespace tipscope::model
