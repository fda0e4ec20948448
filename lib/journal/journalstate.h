// Options and state of a Journal, shared by its front and its writer thread.
#pragma once

#include <QtGlobal>
#include <optional>

namespace tipscope::journal {

enum class JournalState {
    Opening, // the writer thread is opening the file (appends wait in memory)
    Ready,   // appends are written
    Failed,  // cannot write (see errorText()); appends wait in memory up to the backlog limit
    Closed   // close() was called
};

// Why a journal cannot be used, by what would help: waiting (Locked, Full, DiskError), or a
// person (ReadOnly: the folder or file; Damaged; Foreign: another program's file; Newer: a newer
// TipScope's schema; Missing: no file where one is read). tipscope-cli gives each its own exit
// status and tipscope-agent stops on the kinds that waiting cannot mend (docs/user-guide.md).
enum class JournalProblem {
    None,
    Missing,
    Locked,
    Full,
    DiskError,
    ReadOnly,
    Damaged,
    Foreign,
    Newer,
    Other
};

// Whether waiting may mend `problem` (another program's lock, a full disk, a disk's error).
[[nodiscard]] constexpr bool isPassing(JournalProblem problem) {
    return problem == JournalProblem::Locked || problem == JournalProblem::Full ||
           problem == JournalProblem::DiskError;
}

struct JournalOptions {
    // Unset: the retention stored in the file (journalsettings.h), a year when none is. Set: this
    // program's own until setRetentionDays() stores one (tests and benchmarks keep everything).
    std::optional<int> retentionDays;
    // A hard cap on the file (0: none). Reaching it behaves like a full disk.
    qint64 maxSizeBytes = 0;
    // Records waiting in memory (queued or held while the journal cannot write) above which an
    // append is counted lost instead of kept.
    int backlogLimit = 10000;
    int maxBatch = 2000;        // records per transaction
    int retryIntervalMs = 5000; // how often a failed journal tries again
    int pruneIntervalMs = 3600000;
    int pruneBatch = 500; // rows per pruning transaction, so appends wait little
};

} // namespace tipscope::journal
