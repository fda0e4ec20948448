#include "filenamepart.h"

namespace tipscope::base::io {

QString fileNamePart(const QString &name) {
    QString part;
    for (const QChar c : name.left(kFileNamePartChars)) {
        const bool unsafe = c == QLatin1Char('/') || c == QLatin1Char('\\') ||
                            c.category() == QChar::Other_Control ||
                            c.category() == QChar::Other_Format || c.isSurrogate() ||
                            c.category() == QChar::Other_NotAssigned;
        part.append(unsafe ? QLatin1Char('_') : c);
    }
    if (part.count(QLatin1Char('.')) == part.size())
        part.fill(QLatin1Char('_'), qMax<qsizetype>(part.size(), 1));
    return part;
}

} // namespace tipscope::base::io
