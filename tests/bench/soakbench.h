// `tipscope-bench soak`: a bounded fault-injection soak of the whole client stack.
//
// tipscope-sim serves a DME on a PTY (--link, paced at 19200 baud). It loses the answer of 1% of
// the requests it carried out, corrupts 1% of answers (bit flips, wrong BCC, cut short), puts
// noise before 1%, and loses 0.5% of the requests on their way and flips a bit in another 0.5%;
// FaultWindows adds NAKs (0.5% of requests) and answers delayed past the timeout (0.5%), and
// every --unplug-every seconds the PTY is unplugged and plugged back a second later. Meanwhile
// the client, a link::Line with a StationModel and a PollScheduler polling all 4 ports, performs
// a stream of writes with read-back (WriteStream: Parameter::apply on ST1..ST4 and A11..A41),
// each under its own id, and after each one the device's memory is compared with the shadow
// (the simulator's "get", past the line).
//
// At the end the stream is drained and every setting the device stores is compared: the written
// codes with the ledger, the others with their values before the first write. Figures, one
// "name: value unit" per line: transactions, faults injected (the simulator's stats and the
// windows), faults detected by kind (LinkStats), writes verified / failed (by reason) / lost /
// reported twice, device checks and mismatches, values on the device that no write explains,
// requests pending at the end, RSS at start and end, and for each unplug the time until the line
// noticed and until the first answer after the plug. The exit status is 0 only when no write was
// lost or reported twice, the device never held what the shadow does not allow, nothing is
// pending and the line recovered every time.
#pragma once

#include <QStringList>

namespace tipscope::bench {

// `args` are the arguments after "soak". Returns the process exit status.
[[nodiscard]] int runSoakBench(const QStringList &args);

} // namespace tipscope::bench
