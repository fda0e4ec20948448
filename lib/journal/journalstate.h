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
