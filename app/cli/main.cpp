// tipscope-cli: the command-line face of TipScope, for technicians' scripts and for testing the
// whole stack without a window.
#include "clicommands.h"
#include "cliworkspace.h"
#include "i18n/translations.h"

#include <QCoreApplication>

using namespace tipscope::cli;

int main(int argc, char *argv[]) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("tipscope-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TIPSCOPE_VERSION));
    // Messages follow the system's language (LANGUAGE, LC_ALL, LC_MESSAGES, LANG); what the
    // commands print as data keeps the protocol's own format.
    tipscope::i18n::installTranslators(app, QStringLiteral("system"));
    QTextStream out(stdout);
    QTextStream err(stderr);
    const auto options = CliParser::parse(app.arguments());
    if (!options) {
        err << "tipscope-cli: " << options.error() << "\n\n" << CliParser::usage();
        return kUsage;
    }
    if (options->showHelp) {
        out << CliParser::usage();
        return kOk;
    }
    if (options->showVersion) {
        out << "tipscope-cli " << QCoreApplication::applicationVersion() << Qt::endl;
        return kOk;
    }
    if (options->command == QLatin1String("monitor") &&
        options->values.contains(QStringLiteral("mqtt")))
        return runMonitorMqtt(*options, out, err);
    if (options->command == QLatin1String("monitor"))
        return runMonitor(*options, out, err);
    if (!options->workspace.isEmpty())
        return runWorkspace(*options, out, err);
    if (options->command == QLatin1String("commands"))
        return runCommands(*options, out, err);
    if (options->command == QLatin1String("measure"))
        return runMeasure(*options, out, err);
    if (options->command == QLatin1String("record"))
        return runRecord(*options, out, err);
    if (options->command == QLatin1String("joints"))
        return runJoints(*options, out, err);
    if (options->command == QLatin1String("context"))
        return runContext(*options, out, err);
    if (options->command == QLatin1String("limits"))
        return runLimits(*options, out, err);
    if (options->command == QLatin1String("journal"))
        return runJournal(*options, out, err);

    CliSession session(*options);
    if (const int rc = session.open(); rc != kOk)
        return rc;
    return runOnLine(session);
}
