#include "catalogtext.h"

#include <QCoreApplication>

namespace tipscope::protocol {

QString catalogText(const QString &english) {
    if (english.isEmpty())
        return english; // the unset digits of flags have empty labels: nothing to look up
    return QCoreApplication::translate("Catalog", english.toUtf8().constData());
}

QString catalogText(const QString &english, Wording wording) {
    return wording == Wording::Translated ? catalogText(english) : english;
}

} // namespace tipscope::protocol
