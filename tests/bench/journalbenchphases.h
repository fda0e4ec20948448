// The phases of `tipscope-bench journal` (journalbench.h says what each measures).
#pragma once

#include "journal/journal.h"

#include <QString>

namespace tipscope::bench {

struct JournalBenchOptions {
    int seconds = 5;
    int rows = 1'000'000;
    int queries = 25;
};

// Record i of a line of 10 stations with 4 ports each, at the given time; every field set.
[[nodiscard]] model::JointRecord benchJoint(qint64 i, qint64 startMs);
[[nodiscard]] journal::JournalEvent benchEvent(qint64 i, qint64 timeMs);
// Runs the event loop until the journal has opened; false (and an error) if it failed.
[[nodiscard]] bool waitJournalOpened(journal::Journal &journal);

// Each returns false when the phase could not run (the reason printed as an error).
[[nodiscard]] bool journalSustainedPhase(const JournalBenchOptions &o, const QString &folder);
[[nodiscard]] bool journalLargeFilePhase(const JournalBenchOptions &o, const QString &folder);

} // namespace tipscope::bench
