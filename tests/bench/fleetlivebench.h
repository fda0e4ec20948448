// runFleetLiveBench: a fleet of simulated lines in one workspace, for `tipscope-bench fleet`.
//
// Starts --stations (default 32) `tipscope-sim --tcp 127.0.0.1:0 --pace 19200 --activity`
// processes, detached (a DME and a feeder each, the wire paced like a 19200-baud line, the ports
// soldering and resting as in the demo), opens them all as TCP lines in one model::Workspace,
// shows the fleet overview on the offscreen platform, lets discovery and the first readings
// pass, then measures for --minutes (default 10; fractions such as 0.5 allowed). --by-intervals
// turns each line's filling of its wire off, to compare with polling by the intervals alone;
// --chunk-ms C has the simulators hand each answer over every C ms rather than a byte at a time
// (tipscope-sim --chunk), as a USB adapter's latency timer or a device server's packing does.
// Before the workspace opens, the wire floor (wirefloor.h) is measured on the same simulators for
// 30 s. Prints:
//   fleet.floor_tx_per_s, fleet.floor_cpu_us_per_tx (fleet.floor_user_us_per_tx the user part),
//   fleet.floor_cpu_percent      the floor client filling every wire: its rate, its CPU per
//                                transaction and its share of one core
//   fleet.gui_cpu_percent        this whole process's user + system CPU over the run, % of one
//                                core (target < 5)
//   fleet.sim_cpu_percent        the simulators' together, for context: they share the machine
//   fleet.lineNN_tx_per_s        answered transactions a second of each line
//   fleet.lineNN_wire_limit_tx_per_s  what its paced wire carries: the pace's bytes a second
//                                over the bytes of the line's own request and answer frames per
//                                transaction (its link statistics)
//   fleet.tx_per_s, fleet.wire_limit_tx_per_s   both summed over the lines
//   fleet.rate_ratio             the two sums' ratio (target >= 0.95)
//   fleet.tx_period_ms, fleet.tx_wire_ms   a transaction's mean time and its wire time (the
//                                lines' median); fleet.answer_latency_ms_mean/_p50/_p99, from a
//                                request written to its answer complete (each line's last 1000
//                                answers, pooled), and fleet.after_answer_ms, the rest: from an
//                                answer to the next request written
//   fleet.cpu_us_per_tx          the process's CPU time per transaction
//   fleet.floor_cpu_percent_at_fleet_rate  the floor's CPU per transaction at the fleet's rate:
//                                the least fleet.gui_cpu_percent could be on this machine
//   fleet.cpu_over_floor         fleet.cpu_us_per_tx over fleet.floor_cpu_us_per_tx
//   fleet.tiles, fleet.tile_repaints   the page's tiles, and its repaints during the run
//   fleet.tile_latency_ms_p50/_p99  a sample's arrival to its tile repainted (target p99 < 250)
//   fleet.port<N>_hz, fleet.feeder_hz  samples a second of a station's channel, averaged
// and then, at those rates, the memory of a day of the fleet (printDayMemory(), fleetday.h):
// fleet.memory_mb_24h beside fleet.memory_mb_24h_single_tier. A benchmark: it asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runFleetLiveBench(const QStringList &args);

} // namespace tipscope::bench
