#include "timetext.h"

#include <QLocale>

namespace tipscope::base {

QString isoTimeWithOffset(const QDateTime &time) {
    if (!time.isValid())
        return {};
    // A local time prints without its offset; the same instant as a fixed offset prints with it.
    return time.toOffsetFromUtc(time.offsetFromUtc()).toString(Qt::ISODateWithMs);
}

QString clockText(const QDateTime &time, const QDate &today) {
    const QDateTime local = time.toLocalTime();
    return local.toString(local.date() == today ? QStringLiteral("HH:mm:ss")
                                                : QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

QString secondsText(qint64 ms) {
    return QLocale().toString(double(ms) / 1000, 'f', 1);
}

} // namespace tipscope::base
