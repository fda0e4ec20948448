// runFleetBench: whether a day of a fleet's telemetry fits in memory, for
// `tipscope-bench fleet-memory`.
//
// First the rates: the demo line runs for --seconds (default 30) with every port shown, as the
// Charts page polls them, and each port's and the feeder's samples per second are counted
// (--hz R skips the demo and takes R for every channel). Then a simulated clock fills --hours
// (24) at those rates for --stations (32) stations of four ports and a feeder each: the whole
// fleet into tiered buffers (TelemetryTiers' defaults, what a live session makes), and one
// station into single-tier buffers (what a session made before the tiers: 864,000 samples each),
// which is projected to the fleet rather than filled (about 2 GB). Prints:
//   fleet.demo_port<N>_hz, fleet.demo_feeder_hz   the rates measured (or given)
//   fleet.memory_mb_24h                the tiered fleet's buffers (memoryBytes(), measured)
//   fleet.rss_mb_24h                   the resident set the tiered fleet added
//   fleet.memory_mb_24h_single_tier    one single-tier station times --stations
//   fleet.full_rate_hours              what a tiered port holds at full rate (the least of any)
//   fleet.hours_held                   what a tiered port holds in all (the least of any)
//   fleet.single_tier_hours_held       what a single-tier port holds (the least of any)
//   fleet.summary_budget_mb            the older tier's budget of a port and of a feeder
//   fleet.decimate_day_ms              one station's four ports, six series each, over the day
//                                      at 1920 columns (as a chart asks); median of 9
//   fleet.decimate_day_ms_single_tier  the same from the single-tier buffers
// A benchmark: it asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runFleetBench(const QStringList &args);

} // namespace tipscope::bench
