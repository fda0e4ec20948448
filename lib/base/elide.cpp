#include "elide.h"

#include <QCoreApplication>

namespace tipscope::base {

namespace {
struct ElideTr {
    Q_DECLARE_TR_FUNCTIONS(Elide)
};

void appendShown(QString &out, QChar c) {
    const char16_t u = c.unicode();
    if (u < 0x20 || (u >= 0x7f && u < 0xa0))
        out += QStringLiteral("<%1>").arg(uint(u), 2, 16, QLatin1Char('0')).toUpper();
    else
        out += c;
}
} // namespace

QString elided(const QString &text, int maxChars) {
    // Characters, not UTF-16 units: an emoji counts once and is never cut in half.
    qsizetype characters = 0;
    qsizetype cut = -1;
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text.at(i).isLowSurrogate() && i > 0 && text.at(i - 1).isHighSurrogate())
            continue;
        if (characters == maxChars)
            cut = i;
        ++characters;
    }
    QString out;
    const QStringView shown = cut < 0 ? QStringView(text) : QStringView(text).left(cut);
    out.reserve(shown.size());
    for (QChar c : shown)
        appendShown(out, c);
    if (cut < 0)
        return out;
    return ElideTr::tr("%1… (%2 characters)").arg(out).arg(characters);
}

} // namespace tipscope::base
