#include "datafield.h"

namespace tipscope::protocol {

static bool allDigits(const QByteArray &s) {
    if (s.isEmpty())
        return false;
    for (char c : s)
        if (c < '0' || c > '9')
            return false;
    return true;
}

std::optional<QByteArray> encodeNumber(qint64 value) {
    if (value < kNumberMin || value > kNumberMax)
        return std::nullopt;
    if (value < 0)
        return QByteArray("-") + QByteArray::number(-value).rightJustified(kNumberWidth - 1, '0');
    return QByteArray::number(value).rightJustified(kNumberWidth, '0');
}

std::optional<int> parseNumber(const QByteArray &field) {
    if (field.size() != kNumberWidth)
        return std::nullopt;
    if (field.at(0) == '-') {
        const QByteArray digits = field.mid(1);
        if (!allDigits(digits))
            return std::nullopt;
        return -digits.toInt();
    }
    if (!allDigits(field))
        return std::nullopt;
    return field.toInt();
}

std::optional<QByteArray> encodeDelay(int centiseconds) {
    if (centiseconds < 0 || centiseconds > kDelayMaxCentis)
        return std::nullopt;
    return QByteArray::number(centiseconds / 100).rightJustified(2, '0') + '.' +
           QByteArray::number(centiseconds % 100).rightJustified(2, '0');
}

std::optional<int> parseDelay(const QByteArray &field) {
    if (field.size() != kNumberWidth || field.at(2) != '.')
        return std::nullopt;
    const QByteArray ss = field.left(2);
    const QByteArray cc = field.mid(3, 2);
    if (!allDigits(ss) || !allDigits(cc))
        return std::nullopt;
    return ss.toInt() * 100 + cc.toInt();
}

QByteArray encodeHex(quint64 value, int digits) {
    return QByteArray::number(value, 16).toUpper().rightJustified(digits, '0');
}

std::optional<quint64> parseHex(const QByteArray &field) {
    QByteArray digits = field;
    if (digits.startsWith("0x") || digits.startsWith("0X"))
        digits = digits.mid(2);
    // 16 hex digits hold any 64-bit counter; anything longer is not a counter.
    if (digits.isEmpty() || digits.size() > 16)
        return std::nullopt;
    for (char c : digits) {
        const bool hex = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
        if (!hex)
            return std::nullopt;
    }
    bool ok = false;
    const quint64 v = digits.toULongLong(&ok, 16);
    return ok ? std::optional<quint64>(v) : std::nullopt;
}

std::optional<QString> parseText(const QByteArray &field) {
    for (char c : field)
        if (c < 0x20 || c > 0x7e)
            return std::nullopt;
    return QString::fromLatin1(field).trimmed();
}

} // namespace tipscope::protocol
