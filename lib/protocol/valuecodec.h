// Converts between catalog-typed values and data fields, validates writes, and describes values
// for people. Everything here works in wire units (°C, ‰, dmm, minutes, centiseconds for ss.cc
// delays); display-unit conversion belongs to the model layer. Messages (validate(),
// allowedText(), parse errors) are in the user interface language; a value's description is in
// the Wording asked for, since tipscope-cli prints it as data in the catalog's English.
//
// validate() is the single gate every write passes before it may reach the wire: the CLI, the
// models and the simulator all call it, so a value refused in one place is refused everywhere.
#pragma once

#include "base/outcome.h"
#include "catalog.h"

#include <QString>
#include <optional>

namespace tipscope::protocol {

struct Value {
    bool isText = false;
    qint64 number = 0;
    QString text;

    [[nodiscard]] static Value ofNumber(qint64 n) { return {false, n, {}}; }
    [[nodiscard]] static Value ofText(const QString &t) { return {true, 0, t}; }
    friend bool operator==(const Value &a, const Value &b) {
        return a.isText == b.isText && a.number == b.number && a.text == b.text;
    }
};

// Empty when `value` may be written with `cmd`; otherwise a sentence saying what is allowed.
[[nodiscard]] QString validate(const ResolvedCommand &cmd, qint64 value);
// Empty when `data`, a data field made by hand (`tipscope-cli write --raw`), carries a value
// validate() allows; otherwise why not. Kinds the catalog gives no range (actions, text, hex) are
// not checked: their field is the caller's to make.
[[nodiscard]] QString validateData(const ResolvedCommand &cmd, const QByteArray &data);
// The data field for a write of `value` (validated first), or validate()'s reason if refused.
[[nodiscard]] base::Outcome<QByteArray> encodeWrite(const ResolvedCommand &cmd, qint64 value);
// Decodes the data field of an answer to a read.
[[nodiscard]] std::optional<Value> decodeAnswer(const ResolvedCommand &cmd, const QByteArray &data);
// Parses a value typed by a person: "-50", "350", "1.6" or "01.60" for delays, "disabled",
// an enum label ("Stand", or as the user interface language says it). Numbers are in wire units.
[[nodiscard]] base::Outcome<qint64> parseUserValue(const ResolvedCommand &cmd, const QString &text);
// The value whose label in `labels` is `text`, in the catalog's English (what scripts type) or
// in the user interface language (what messages offer), whatever the case.
[[nodiscard]] std::optional<qint64> labelled(const QMap<int, QString> &labels, const QString &text);
// "350", "1.60", "disabled", "Stand, Cooling", "T245" (no unit).
[[nodiscard]] QString describeValue(const ResolvedCommand &cmd, const Value &value,
                                    Wording wording);
// The wire unit symbol of a command ("°C", "‰", "s" for delays), possibly empty.
[[nodiscard]] QString wireUnitSymbol(const ResolvedCommand &cmd);
// Labels of the set digits of a flags value ("Stand", "Cooling").
[[nodiscard]] QStringList flagLabels(const QList<DigitField> &digits, qint64 value,
                                     Wording wording);
// What a write may carry, for messages and tooltips: "90 to 500 °C in steps of 5, or disabled".
[[nodiscard]] QString allowedText(const ResolvedCommand &cmd);

} // namespace tipscope::protocol
