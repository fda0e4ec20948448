#include "journaldlog.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QtGlobal>
#include <cstdio>

namespace tipscope::agent {

namespace {

const char *priority(QtMsgType type) {
    switch (type) {
    case QtDebugMsg:
        return "<7>";
    case QtInfoMsg:
        return "<6>";
    case QtWarningMsg:
        return "<4>";
    case QtCriticalMsg:
        return "<3>";
    case QtFatalMsg:
        return "<2>";
    }
    return "<6>";
}

void write(QtMsgType type, const QMessageLogContext &context, const QString &message) {
    QByteArray out;
    const bool named =
        type == QtDebugMsg && context.category && qstrcmp(context.category, "default") != 0;
    for (const QString &line : message.split(QLatin1Char('\n'))) {
        out += priority(type);
        if (named)
            out += QByteArray(context.category) + ": ";
        out += line.toUtf8() + '\n';
    }
    std::fwrite(out.constData(), 1, size_t(out.size()), stderr);
    std::fflush(stderr);
}

} // namespace

void installJournaldLog() {
    qInstallMessageHandler(write);
}

} // namespace tipscope::agent
