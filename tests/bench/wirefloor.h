// The wire floor: the least CPU any client spends per transaction on the benches' simulated wires,
// for `tipscope-bench fleet` and `plant` to print beside what TipScope spends.
//
// On loopback the kernel charges the sender for delivering to the receiver and waking it, so
// much of a transaction's cost is the wire's, not the client's, and a CPU target can sit near
// what the machine spends on the I/O alone. measureWireFloor() finds that floor in the same run,
// against the same simulators: one thread, one epoll set over non-blocking TCP sockets to all of
// them, each line carrying one read request at a time (a port's tip temperature, built from the
// catalog), its answer recognised by its ETX and block check alone, the next request sent at
// once. No queue, no decoder, no model, no event loop: what is left is the system calls and the
// wake-ups any client of these wires pays. Each simulator takes the floor's connection as a
// device server's new client, and takes the next client's the same way after it.
#pragma once

#include "simstations.h"

#include <QString>
#include <optional>
#include <vector>

namespace tipscope::bench {

struct WireFloor {
    double txPerS = 0;     // answered transactions a second, summed over the lines
    double cpuUsPerTx = 0; // the measuring thread's user + system CPU time per transaction
    double userUsPerTx = 0;
    std::optional<double> syscallsPerTx; // where the system calls could be counted
    double wakeUpsPerTx = 0;             // the times the thread slept in epoll_wait and woke

    // What the floor costs at another client's rate, in % of one core.
    [[nodiscard]] double cpuPercentAt(double txPerS) const { return cpuUsPerTx * txPerS / 1e4; }
};

// Fills every station's wire for `ms` and measures; nullopt, with `error` set, when a station
// could not be reached or none answered.
[[nodiscard]] std::optional<WireFloor> measureWireFloor(const std::vector<SimStation> &stations,
                                                        int ms, QString *error);

} // namespace tipscope::bench
