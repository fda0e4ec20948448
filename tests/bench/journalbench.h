// `tipscope-bench journal`: what the journal sustains and how fast it answers.
//
// Sustained inserts: joints (then events) appended by the main thread from a 10 ms timer that
// stands in for polling, the writer thread committing in batches; the figures are the committed
// records per second, the main thread's cost per append, and the timer's worst and 99th
// percentile lateness beside the same timer with no journal at all. Large file: a journal of
// --rows joints (default 1,000,000) over a year on 10 stations of 4 ports, built once per run in
// a temporary folder; bytes on disk per joint, then the time of queries by time range and port
// (p50 and p99 over several), by device, port and week, and the aggregates; the same for events.
#pragma once

#include <QStringList>

namespace tipscope::bench {

[[nodiscard]] int runJournalBench(const QStringList &args);

} // namespace tipscope::bench
