// Display units: what people read and type, converted from and to the wire's units.
//
// The wire always carries °C, per mille, tenths and hundredths of a millimetre, "ss.cc" delays
// (held as centiseconds) and whole minutes or hours. People see °C or °F (their choice; an
// adjust offset converts as a difference, without the 32), per cent, millimetres, seconds, and
// the catalog's special values by name ("disabled"). fromDisplay() rounds to the nearest wire
// value; validation then happens on the wire value, so the rules live in one place (the catalog).
#pragma once

#include "protocol/catalog.h"
#include "protocol/valuecodec.h"

#include <QLocale>
#include <QString>
#include <optional>

namespace tipscope::model {

enum class TemperatureUnit { Celsius, Fahrenheit };

struct DisplayFormat {
    double scale = 1; // display = wire * scale + offset
    double offset = 0;
    int decimals = 0;
    QString unit; // "°C", "°F", "%", "mm", "s", ...
};

[[nodiscard]] DisplayFormat displayFormat(const protocol::ResolvedCommand &cmd, TemperatureUnit t);
[[nodiscard]] double toDisplay(const protocol::ResolvedCommand &cmd, qint64 wire,
                               TemperatureUnit t);
[[nodiscard]] qint64 fromDisplay(const protocol::ResolvedCommand &cmd, double display,
                                 TemperatureUnit t);
// "350 °C", "662 °F", "84.0 %", "20.0 mm", "1.60 s", "disabled", "Stand, Cooling", "T245", the
// catalog's words in the user interface language.
[[nodiscard]] QString formatValue(const protocol::ResolvedCommand &cmd, const protocol::Value &v,
                                  TemperatureUnit t);
// A number with its unit, without special-value names ("350 °C").
[[nodiscard]] QString formatNumber(const protocol::ResolvedCommand &cmd, qint64 wire,
                                   TemperatureUnit t);
// Parses what a person typed, in display units (the unit may follow the number) or by a special
// value's or an enum's name. Numbers are read in `locale`, and also with the C locale's point (a
// script's); a value the wire cannot hold exactly (finer than its step) is refused, not rounded:
// nothing is written that was not typed. tipscope-cli passes QLocale::c().
[[nodiscard]] base::Outcome<qint64> parseDisplayText(const protocol::ResolvedCommand &cmd,
                                                     const QString &text, TemperatureUnit t,
                                                     const QLocale &locale = QLocale());

} // namespace tipscope::model
