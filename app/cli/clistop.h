// Ctrl-C and SIGTERM ask a long command (monitor, record) to stop: it then finishes what it
// holds (the journal's last records, the recording's file) and exits with its own status,
// rather than dying by the signal with records still queued.
#pragma once

class QEventLoop;

namespace tipscope::cli {

// A signal handler may only set a lock-free flag; a loop looks at it this often.
inline constexpr int kStopCheckMs = 25;

// From now on SIGINT and SIGTERM only set the flag below.
void catchStopSignals();
[[nodiscard]] bool stopRequested();
// Quits `loop` once a stop is asked for; until `loop` is destroyed.
void quitLoopOnStop(QEventLoop &loop);

} // namespace tipscope::cli
