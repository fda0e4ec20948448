// `tipscope-bench link`: what the real link stack achieves against tipscope-sim over a PTY.
//
// Four phases, each with its own simulator process and line: paced reads against the wire limit
// of 19200 baud; unpaced reads for the stack's own cost (rate and CPU per transaction); a user
// write's latency while four ports are polled flat out on a paced line; and the time a
// Discovery (Mode::Auto) takes on a DME with a feeder. Figures go to standard output one per
// line; a phase that cannot run (no simulator, no answer) ends the run with exit status 1.
#pragma once

#include <QStringList>

namespace tipscope::bench {

// `args` are the arguments after "link". Returns the process exit status.
[[nodiscard]] int runLinkBench(const QStringList &args);

} // namespace tipscope::bench
