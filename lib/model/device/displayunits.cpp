#include "displayunits.h"

#include <QCoreApplication>
#include <QLocale>
#include <cmath>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct DisplayUnitsTr {
    Q_DECLARE_TR_FUNCTIONS(DisplayUnits)
};
} // namespace

DisplayFormat displayFormat(const ResolvedCommand &cmd, TemperatureUnit t) {
    const QString &key = cmd.spec->unit;
    const bool fahrenheit = t == TemperatureUnit::Fahrenheit;
    if (key == QLatin1String("degC"))
        return fahrenheit ? DisplayFormat{1.8, 32, 0, QStringLiteral("°F")}
                          : DisplayFormat{1, 0, 0, QStringLiteral("°C")};
    if (key == QLatin1String("degCDelta"))
        return fahrenheit ? DisplayFormat{1.8, 0, 0, QStringLiteral("°F")}
                          : DisplayFormat{1, 0, 0, QStringLiteral("°C")};
    if (cmd.spec->kind == ValueKind::Delay)
        return {0.01, 0, 2, QStringLiteral("s")};
    if (const Unit *u = Catalog::builtin().unit(key))
        return {u->scale, 0, u->decimals, u->display};
    return {};
}

double toDisplay(const ResolvedCommand &cmd, qint64 wire, TemperatureUnit t) {
    const DisplayFormat f = displayFormat(cmd, t);
    return double(wire) * f.scale + f.offset;
}

qint64 fromDisplay(const ResolvedCommand &cmd, double display, TemperatureUnit t) {
    const DisplayFormat f = displayFormat(cmd, t);
    return qint64(std::llround((display - f.offset) / f.scale));
}

QString formatNumber(const ResolvedCommand &cmd, qint64 wire, TemperatureUnit t) {
    const DisplayFormat f = displayFormat(cmd, t);
    const QString number = QLocale().toString(toDisplay(cmd, wire, t), 'f', f.decimals);
    return f.unit.isEmpty() ? number : number + QLatin1Char(' ') + f.unit;
}

QString formatValue(const ResolvedCommand &cmd, const Value &v, TemperatureUnit t) {
    if (v.isText)
        return v.text;
    if (cmd.spec->special.contains(int(v.number)))
        return catalogText(cmd.spec->special.value(int(v.number)));
    switch (cmd.spec->kind) {
    case ValueKind::Enum:
    case ValueKind::Flags:
    case ValueKind::Text:
        return describeValue(cmd, v, Wording::Translated);
    default:
        return formatNumber(cmd, v.number, t);
    }
}

base::Outcome<qint64> parseDisplayText(const ResolvedCommand &cmd, const QString &text,
                                       TemperatureUnit t, const QLocale &locale) {
    const QString s = text.trimmed();
    if (auto special = labelled(cmd.spec->special, s))
        return *special;
    if (cmd.spec->kind == ValueKind::Enum || cmd.spec->kind == ValueKind::Flags ||
        cmd.spec->kind == ValueKind::Action)
        return parseUserValue(cmd, s);
    const DisplayFormat f = displayFormat(cmd, t);
    QString number = s;
    if (!f.unit.isEmpty() && number.endsWith(f.unit))
        number.chop(f.unit.size());
    bool ok = false;
    double d = locale.toDouble(number.trimmed(), &ok);
    if (!ok)
        d = number.trimmed().toDouble(&ok); // a script may use the C locale's decimal point
    if (!ok || !std::isfinite(d))
        return base::failure(DisplayUnitsTr::tr("'%1' is not a number").arg(s));
    // Far beyond any wire value (which the catalog's limits then refuse by name): rounding it
    // would overflow.
    const double exact = (d - f.offset) / f.scale;
    if (std::fabs(exact) > 1e15)
        return base::failure(DisplayUnitsTr::tr("'%1' is far outside what %2 can take")
                                 .arg(s, catalogText(cmd.spec->name)));
    const qint64 wire = fromDisplay(cmd, d, t);
    if (std::fabs(toDisplay(cmd, wire, t) - d) > 1e-9 * qMax(1.0, std::fabs(d))) {
        // Nothing is written that was not typed; the two values the station can hold around it
        // are named, as a whole °F is rarely a whole °C.
        const auto below = qint64(std::floor(exact));
        return base::failure(DisplayUnitsTr::tr("%1 lies between the values %2 can take: %3 or %4")
                                 .arg(s, catalogText(cmd.spec->name), formatNumber(cmd, below, t),
                                      formatNumber(cmd, below + 1, t)));
    }
    return wire;
}

} // namespace tipscope::model
