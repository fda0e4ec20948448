// Command-line parsing for tipscope-cli. Hand-written rather than QCommandLineParser because
// values are typed the way people write them: `write A12 -50` must not read "-50" as an option,
// and a command's own options may follow it (`read --raw ST1`, `write LEN --raw 00200`).
#pragma once

#include "base/outcome.h"
#include "link/line.h"
#include "model/context/workcontext.h"
#include "model/joints/jointlimitrules.h"
#include "model/session.h"

#include <QCoreApplication>
#include <QStringList>
#include <memory>
#include <optional>

namespace tipscope::cli {

enum ExitCode {
    kOk = 0,
    kUsage = 1,
    kRefused = 2,
    kNak = 3,
    kNoAnswer = 4,
    kTransport = 5,
    // The journal, by kind of problem (journal::JournalProblem; docs/user-guide.md).
    kJournalMissing = 6,
    kJournalDamaged = 7, // damaged inside, or not a TipScope journal
    kJournalNewer = 8,
    kJournalLocked = 9,
    kJournalInaccessible = 10, // the file or its folder cannot be read or written
    kJournalDisk = 11,         // the disk is full or reported an error
};

struct CliOptions {
    // The session's own: `--addr` and `--no-addr` ask what a workspace line's settings ask.
    using Addressing = model::Session::Addressing;

    link::LineSettings line;
    bool demo = false;
    bool demoActivity = false; // the demo's station solders and rests, its feeder feeds
    Addressing addressing = Addressing::Auto;
    int targetAddress = 1;
    bool verbose = false;
    bool showHelp = false;
    bool showVersion = false;

    QString command;
    QStringList args;              // the command's positional arguments
    QStringList flags;             // the command's options without values: "raw", "json", "scan"
    QMap<QString, QString> values; // the command's options with values: interval, csv, ...

    QString workspace; // --workspace FILE: the command runs on every line of the workspace
    QString lineName;  // the workspace line a run is for (see cliworkspace.h)
};

class CliParser {
    Q_DECLARE_TR_FUNCTIONS(CliParser)
public:
    // The options, or the usage error.
    [[nodiscard]] static base::Outcome<CliOptions> parse(const QStringList &arguments);
    [[nodiscard]] static QString usage();
};

} // namespace tipscope::cli
