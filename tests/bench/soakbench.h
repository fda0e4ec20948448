// `tipscope-bench soak`: a bounded fault-injection soak of the whole client stack.
//
// tipscope-sim serves a DME on a PTY (--link, paced at 19200 baud) and drops 1% of requests,
// corrupts 1% of answers (bit flips, wrong BCC, cut short) and puts noise before 1%; FaultWindows
// adds NAKs (0.5% of requests) and answers delayed past the timeout (0.5%), and every
// --unplug-every seconds the PTY is unplugged and plugged back a second later. Meanwhile the
// client, a link::Line with a StationModel and a PollScheduler polling all 4 ports, performs a
// stream of writes with read-back (WriteStream: Parameter::apply on ST1..ST4 and A11..A41).
//
// At the end the stream is drained, faults are switched off, every written code is read back
// from the simulator and compared with the ledger. Figures, one "name: value unit" per line:
// transactions, faults injected (the simulator's stats and the windows), faults detected by kind
// (LinkStats), writes verified / failed (by reason) / lost, values on the device that no write
// explains, requests pending at the end, RSS at start and end, and for each unplug the time until
// the line noticed and until the first answer after the plug. The exit status is 0 only when no
// write was lost, no value is unexpected, nothing is pending and the line recovered every time.
#pragma once

#include <QStringList>

namespace tipscope::bench {

// `args` are the arguments after "soak". Returns the process exit status.
[[nodiscard]] int runSoakBench(const QStringList &args);

} // namespace tipscope::bench
