// Data-field formats of the robot protocol, both directions.
//
//  - Number: five characters, zero-padded, a minus sign in the first place for negatives
//    ("00375", "-0050"); the range is therefore -9999..99999.
//  - Delay: "ss.cc", seconds and hundredths ("01.60" = 1.6 s), held as centiseconds.
//  - Disabled: the number 99999 where a command allows "disabled" / "not set".
//  - Hex: a counter in hexadecimal (R-DLx); see docs/protocol-notes.md for the accepted lengths.
//  - Text: model name and software version, any printable length.
// Every parser returns nullopt for malformed input instead of guessing.
#pragma once

#include <QByteArray>
#include <QString>
#include <optional>

namespace tipscope::protocol {

inline constexpr int kNumberWidth = 5;
inline constexpr int kNumberMin = -9999;
inline constexpr int kNumberMax = 99999;
inline constexpr int kDisabled = 99999;
inline constexpr int kDelayMaxCentis = 9999; // "99.99"

[[nodiscard]] std::optional<QByteArray> encodeNumber(qint64 value);
[[nodiscard]] std::optional<int> parseNumber(const QByteArray &field);

[[nodiscard]] std::optional<QByteArray> encodeDelay(int centiseconds);
[[nodiscard]] std::optional<int> parseDelay(const QByteArray &field);

[[nodiscard]] QByteArray encodeHex(quint64 value, int digits = 8);
[[nodiscard]] std::optional<quint64> parseHex(const QByteArray &field);

[[nodiscard]] std::optional<QString> parseText(const QByteArray &field);

} // namespace tipscope::protocol
