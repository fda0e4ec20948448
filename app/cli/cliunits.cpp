#include "cliunits.h"

#include "model/device/displayunits.h"

namespace tipscope::cli {

using namespace tipscope::protocol;

namespace {
constexpr model::TemperatureUnit kCelsius = model::TemperatureUnit::Celsius;
} // namespace

bool shownConverted(const ResolvedCommand &cmd) {
    // An ALE's fed length (DLx) comes as hex, and is a length all the same. Power stays in ‰, as
    // scripts have always written a power limit.
    const bool number = cmd.spec->kind == ValueKind::Number || cmd.spec->kind == ValueKind::Hex;
    const model::DisplayFormat f = model::displayFormat(cmd, kCelsius);
    const bool length = f.unit == QLatin1String("mm") || f.unit == QLatin1String("mm/s");
    return number && length && f.scale != 1;
}

QString shownNumber(const ResolvedCommand &cmd, qint64 wire) {
    const model::DisplayFormat f = model::displayFormat(cmd, kCelsius);
    return QString::number(model::toDisplay(cmd, wire, kCelsius), 'f', f.decimals) +
           QLatin1Char(' ') + f.unit;
}

} // namespace tipscope::cli
