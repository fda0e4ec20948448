// How tipscope-cli shows and reads lengths and speeds: in the units the GUI shows ("25.0 mm",
// "12.5 mm/s", not "250 dmm"), through the GUI's own conversion (model::displayFormat), with the
// C locale's point, because this is data for scripts. Everything else is shown as the catalog
// writes it (temperatures in °C, power in ‰, delays in s, minutes, enums).
#pragma once

#include "protocol/catalog.h"

#include <QString>
#include <optional>

namespace tipscope::cli {

// Whether `cmd` is a length or a speed, shown converted from the wire's unit (dmm, cmm, dmm/s).
[[nodiscard]] bool shownConverted(const protocol::ResolvedCommand &cmd);
// "25.0 mm" for a wire value of 250 dmm. What is typed in that unit is read by
// model::parseDisplayText() with the C locale.
[[nodiscard]] QString shownNumber(const protocol::ResolvedCommand &cmd, qint64 wire);
} // namespace tipscope::cli
