#include "eventtext.h"

#include <QCoreApplication>

namespace tipscope::model {

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(EventText)
};
} // namespace

QString repeatedEventText(const QString &text, int count, const QString &lastTime) {
    if (count <= 1)
        return text;
    return Tr::tr("%1 (%n times, until %2)", nullptr, count).arg(text, lastTime);
}

} // namespace tipscope::model
