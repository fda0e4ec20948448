#include "eventtext.h"

#include <QCoreApplication>

namespace tipscope::model {

namespace {
struct EventTextTr {
    Q_DECLARE_TR_FUNCTIONS(EventText)
};
} // namespace

QString repeatedEventText(const QString &text, int count, const QString &lastTime) {
    if (count <= 1)
        return text;
    return EventTextTr::tr("%1 (%n times, until %2)", nullptr, count).arg(text, lastTime);
}

QString asSentence(QString text) {
    if (!text.isEmpty())
        text[0] = text.at(0).toUpper();
    return text;
}

} // namespace tipscope::model
