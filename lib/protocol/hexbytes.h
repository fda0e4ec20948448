// Hex text <-> bytes for people: the console's "send raw frame" field and tipscope-cli send.
// Accepts "02 30 30", "023030", "0x02,0x30", upper or lower case; refuses anything else with a
// message that points at the first bad character.
#pragma once

#include "base/outcome.h"

#include <QByteArray>
#include <QString>

namespace tipscope::protocol {

inline constexpr int kMaxHexInputBytes = 4096;

[[nodiscard]] base::Outcome<QByteArray> parseHexBytes(const QString &text);
// "02 30 30 ..." with a space between bytes.
[[nodiscard]] QString toHexText(const QByteArray &bytes);
// Printable ASCII as is, control bytes by name: "<STX>0001RSMN<ETX><3E>".
[[nodiscard]] QString toAsciiText(const QByteArray &bytes);

} // namespace tipscope::protocol
