#include "cliunits.h"

#include "model/displayunits.h"
#include "protocol/elide.h"
#include "protocol/valuecodec.h"

#include <QCoreApplication>
#include <cmath>

namespace tipscope::cli {

using namespace tipscope::protocol;

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(CliUnits)
};

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

protocol::Outcome<qint64> parseShown(const ResolvedCommand &cmd, const QString &typed) {
    QString t = typed.trimmed();
    if (const auto special = labelled(cmd.spec->special, t))
        return *special;
    const model::DisplayFormat f = model::displayFormat(cmd, kCelsius);
    if (t.endsWith(f.unit))
        t.chop(f.unit.size());
    bool ok = false;
    const double shown = t.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(shown)) {
        return protocol::failure(Tr::tr("'%1' is not a number; %2 takes %3")
                                     .arg(elided(typed), QString::fromLatin1(cmd.code), f.unit));
    }
    const qint64 wire = model::fromDisplay(cmd, shown, kCelsius);
    if (std::fabs(model::toDisplay(cmd, wire, kCelsius) - shown) >
        1e-9 * qMax(1.0, std::fabs(shown))) {
        return protocol::failure(Tr::tr("%1 takes steps of %2 %3")
                                     .arg(QString::fromLatin1(cmd.code),
                                          QString::number(f.scale, 'f', f.decimals), f.unit));
    }
    return wire;
}

} // namespace tipscope::cli
