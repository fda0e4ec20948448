#include "problemlevel.h"

#include <QApplication>
#include <QColor>
#include <QStyle>

namespace tipscope::gui {

using model::Event;

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(ProblemLevel)
};
} // namespace

Level levelOf(const QString &catalogSeverity) {
    if (catalogSeverity == QLatin1String("ok"))
        return Level::Ok;
    if (catalogSeverity == QLatin1String("info"))
        return Level::Info;
    if (catalogSeverity == QLatin1String("warning"))
        return Level::Warning;
    return Level::Error;
}

Level levelOf(Event::Severity severity) {
    switch (severity) {
    case Event::Severity::Info:
        return Level::Info;
    case Event::Severity::Warning:
        return Level::Warning;
    case Event::Severity::Error:
        return Level::Error;
    }
    return Level::Error;
}

QString levelName(Level level) {
    switch (level) {
    case Level::Unknown:
        return Tr::tr("Not read yet");
    case Level::Ok:
        return Tr::tr("OK");
    case Level::Info:
        return Tr::tr("Info");
    case Level::Warning:
        return Tr::tr("Warning");
    case Level::Error:
        return Tr::tr("Error");
    }
    return {};
}

QIcon levelIcon(Level level) {
    const QStyle *style = QApplication::style();
    switch (level) {
    case Level::Unknown:
        return {};
    case Level::Ok:
        return style->standardIcon(QStyle::SP_DialogApplyButton);
    case Level::Info:
        return style->standardIcon(QStyle::SP_MessageBoxInformation);
    case Level::Warning:
        return style->standardIcon(QStyle::SP_MessageBoxWarning);
    case Level::Error:
        return style->standardIcon(QStyle::SP_MessageBoxCritical);
    }
    return {};
}

// Translucent, so the tint reads on light and dark palettes alike.
QVariant levelTint(Level level) {
    switch (level) {
    case Level::Error:
        return QColor(220, 40, 40, 70);
    case Level::Warning:
        return QColor(235, 165, 0, 80);
    case Level::Info:
        return QColor(40, 120, 220, 35);
    default:
        return {};
    }
}

} // namespace tipscope::gui
