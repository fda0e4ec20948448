#include "journalbench.h"

#include "benchsupport.h"
#include "journalbenchphases.h"

#include <QCommandLineParser>
#include <QTemporaryDir>
#include <QTextStream>

namespace tipscope::bench {

namespace {

// Reads a whole number option within [low, high] into `value`; false (and an error) otherwise.
bool readNumber(const QCommandLineParser &p, const QString &name, int low, int high, int *value) {
    if (!p.isSet(name))
        return true;
    bool ok = false;
    const int v = p.value(name).toInt(&ok);
    if (!ok || v < low || v > high) {
        printError(
            QStringLiteral("--%1 takes a whole number from %2 to %3").arg(name).arg(low).arg(high));
        return false;
    }
    *value = v;
    return true;
}

// Returns -1 to go on, or the exit status to end with (0 after --help).
int parseOptions(const QStringList &args, JournalBenchOptions *o) {
    QCommandLineParser p;
    p.addOptions({
        {QStringLiteral("seconds"), QStringLiteral("Time per sustained-insert run (default 5)."),
         QStringLiteral("N")},
        {QStringLiteral("rows"),
         QStringLiteral("Joints and events in the large file (default 1000000)."),
         QStringLiteral("N")},
        {QStringLiteral("queries"), QStringLiteral("Queries per kind (default 25)."),
         QStringLiteral("N")},
        {{QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Show this help.")},
    });
    const QString help = QStringLiteral("Usage: tipscope-bench journal [options]\n") +
                         p.helpText().section(QLatin1Char('\n'), 1);
    if (!p.parse(QStringList{QStringLiteral("tipscope-bench journal")} + args) ||
        !p.positionalArguments().isEmpty()) {
        printError(p.errorText().isEmpty() ? QStringLiteral("unexpected arguments")
                                           : p.errorText());
        printNote(help);
        return 1;
    }
    if (p.isSet(QStringLiteral("help"))) {
        QTextStream(stdout) << help;
        return 0;
    }
    const bool ok = readNumber(p, QStringLiteral("seconds"), 1, 3600, &o->seconds) &&
                    readNumber(p, QStringLiteral("rows"), 1000, 100'000'000, &o->rows) &&
                    readNumber(p, QStringLiteral("queries"), 1, 10'000, &o->queries);
    return ok ? -1 : 1;
}

} // namespace

int runJournalBench(const QStringList &args) {
    JournalBenchOptions o;
    if (const int status = parseOptions(args, &o); status >= 0)
        return status;
    QTemporaryDir folder;
    if (!folder.isValid()) {
        printError(QStringLiteral("cannot make a temporary folder: %1").arg(folder.errorString()));
        return 1;
    }
    printFigure(QStringLiteral("journal.seconds_per_run"), o.seconds, QStringLiteral("s"), 0);
    printFigure(QStringLiteral("journal.rows"), o.rows, QStringLiteral("rows"), 0);
    return journalSustainedPhase(o, folder.path()) && journalLargeFilePhase(o, folder.path()) ? 0
                                                                                              : 1;
}

} // namespace tipscope::bench
