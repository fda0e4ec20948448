// runReplayBench: what reading a recording costs, for `tipscope-bench replay`. Writes files to a
// temporary folder, reads each as replay does (ChartCsvReader::readFile(), the code the loader
// runs on its thread) and prints, per file, one "name: value unit" line each:
//   replay.<file>.file_mb            the file's size
//   replay.<file>.seconds            the time to read it (or to refuse it)
//   replay.<file>.mb_per_s           read speed, file size over that time
//   replay.<file>.read_mb            bytes read before the answer (less than the file when refused)
//   replay.<file>.peak_rss_ratio     peak resident set during the read, above what it was before,
//                                    over the file's size (the promise: at most 2)
//   replay.<file>.held_ratio         what the recording holds (ChartRecording::memoryBytes()) over
//                                    the file's size; 0 when refused
//   replay.<file>.result             "replayed N rows" or the reader's refusal
// The files: `samples` (--mb MB, default 200, of a station's four ports and a feeder as the
// Charts page records them, an event every 300 rows), `events` (a fifth of that, an event on
// every row), `comments` (84 MB of "# channel" lines, the attack of issue 14), `dense` (255
// channels of one digit each: more samples per byte than TipScope writes), and `fifo` (rows
// streamed through a FIFO past the 1 GiB limit; skipped with --no-fifo). A benchmark: it
// asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runReplayBench(const QStringList &args);

} // namespace tipscope::bench
