#include "hexbytes.h"

#include "frame.h"

#include <QCoreApplication>

namespace tipscope::protocol {

namespace {
struct HexBytesTr {
    Q_DECLARE_TR_FUNCTIONS(HexBytes)
};
} // namespace

static int hexValue(QChar c) {
    const char16_t u = c.unicode();
    if (u >= '0' && u <= '9')
        return u - '0';
    if (u >= 'a' && u <= 'f')
        return u - 'a' + 10;
    if (u >= 'A' && u <= 'F')
        return u - 'A' + 10;
    return -1;
}

base::Outcome<QByteArray> parseHexBytes(const QString &text) {
    const auto fail = [](const QString &why) { return base::failure(why); };
    QByteArray out;
    int pending = -1;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (c.isSpace() || c == QLatin1Char(',') || c == QLatin1Char(':')) {
            if (pending >= 0)
                return fail(
                    HexBytesTr::tr("odd number of hex digits before position %1").arg(i + 1));
            continue;
        }
        if (pending < 0 && c == QLatin1Char('0') && i + 1 < text.size() &&
            (text.at(i + 1) == QLatin1Char('x') || text.at(i + 1) == QLatin1Char('X'))) {
            ++i; // "0x" prefix of one byte
            continue;
        }
        const int v = hexValue(c);
        if (v < 0)
            return fail(HexBytesTr::tr("'%1' at position %2 is not a hex digit").arg(c).arg(i + 1));
        if (pending < 0) {
            pending = v;
        } else {
            out.append(char(pending * 16 + v));
            pending = -1;
            if (out.size() > kMaxHexInputBytes)
                return fail(HexBytesTr::tr("more than %1 bytes").arg(kMaxHexInputBytes));
        }
    }
    if (pending >= 0)
        return fail(HexBytesTr::tr("odd number of hex digits"));
    if (out.isEmpty())
        return fail(HexBytesTr::tr("no bytes given"));
    return out;
}

QString toHexText(const QByteArray &bytes) {
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

QString toAsciiText(const QByteArray &bytes) {
    QString s;
    for (char b : bytes) {
        if (b == kStx)
            s += QStringLiteral("<STX>");
        else if (b == kEtx)
            s += QStringLiteral("<ETX>");
        else if (b >= 0x20 && b <= 0x7e)
            s += QLatin1Char(b);
        else
            s += QStringLiteral("<%1>").arg(quint8(b), 2, 16, QLatin1Char('0')).toUpper();
    }
    return s;
}

} // namespace tipscope::protocol
