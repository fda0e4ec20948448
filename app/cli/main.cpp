// tipscope-cli: the command-line face of TipScope, for technicians' scripts and for testing the
// whole stack without a window.
#include "clicommands.h"
#include "cliworkspace.h"
#include "i18n/translations.h"
#include "link/epolldispatcher.h"

#include <QGuiApplication>
#include <cstring>
#include <memory>

using namespace tipscope::cli;

namespace {
// `board ... --pdf FILE`: the only command that lays text out.
bool wantsPdf(int argc, char *argv[]) {
    bool board = false;
    bool pdf = false;
    for (int i = 1; i < argc; ++i) {
        board = board || std::strcmp(argv[i], "board") == 0;
        pdf = pdf || std::strncmp(argv[i], "--pdf", 5) == 0;
    }
    return board && pdf;
}

// A PDF needs fonts, and Qt gives fonts only to a QGuiApplication. The offscreen platform needs
// no display (a cron job, an SSH session) and the command shows no window, so it is forced; every
// other command keeps the plain QCoreApplication, which loads no platform plugin at all.
std::unique_ptr<QCoreApplication> makeApplication(int &argc, char *argv[]) {
    if (!wantsPdf(argc, argv)) {
        // A monitor of a workspace serves dozens of lines: each turn of the loop costs what is
        // ready, not what is watched (docs/performance.md). A window system needs Qt's own loop.
        (void)tipscope::link::useEpollUnlessTold();
        return std::make_unique<QCoreApplication>(argc, argv);
    }
    qputenv("QT_QPA_PLATFORM", "offscreen");
    return std::make_unique<QGuiApplication>(argc, argv);
}
} // namespace

int main(int argc, char *argv[]) {
    const std::unique_ptr<QCoreApplication> application = makeApplication(argc, argv);
    QCoreApplication &app = *application;
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
        (options->values.contains(QStringLiteral("mqtt")) ||
         options->values.contains(QStringLiteral("cfx"))))
        return runMonitorPlant(*options, out, err);
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
    if (options->command == QLatin1String("board"))
        return runBoard(*options, out, err);
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
