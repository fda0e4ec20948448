#include "problemlevel.h"

#include "protocol/catalog.h"

#include <QCoreApplication>

namespace tipscope::model {

namespace {
struct ProblemLevelTr {
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

Level levelOf(const protocol::Catalog &catalog, const QString &tableName, std::optional<int> code) {
    return code ? levelOf(catalog.severity(tableName, *code)) : Level::Unknown;
}

QString levelName(Level level) {
    switch (level) {
    case Level::Unknown:
        return ProblemLevelTr::tr("Not read yet");
    case Level::Ok:
        return ProblemLevelTr::tr("OK");
    case Level::Info:
        return ProblemLevelTr::tr("Info");
    case Level::Warning:
        return ProblemLevelTr::tr("Warning");
    case Level::Error:
        return ProblemLevelTr::tr("Error");
    }
    return {};
}

} // namespace tipscope::model
