// A day of a fleet's telemetry in memory, shared by `tipscope-bench fleet-memory` (at the demo's
// rates) and `tipscope-bench fleet` (at the rates a workspace of simulators achieved).
//
// printDayMemory() fills `hours` at the given per-channel sample rates on a simulated clock for
// `stations` stations of four ports and a feeder each: the whole fleet into tiered buffers
// (TelemetryTiers' defaults, what a live session makes), and one station into single-tier buffers
// (what a session made before the tiers: 864,000 samples each), which is projected to the fleet
// rather than filled (about 2 GB). It prints:
//   fleet.summary_budget_mb_port/_feeder  the older tier's budget of a port and of a feeder
//   fleet.memory_mb_24h                the tiered fleet's buffers (memoryBytes(), measured)
//   fleet.rss_mb_24h                   the resident set the tiered fleet added
//   fleet.full_rate_hours              what a tiered port holds at full rate (the least of any)
//   fleet.hours_held                   what a tiered port holds in all (the least of any)
//   fleet.decimate_day_ms              one station's four ports, six series each, over the day
//                                      at 1920 columns (as a chart asks); median of 9
//   fleet.memory_mb_24h_single_tier    one single-tier station times `stations`
//   fleet.single_tier_hours_held       what a single-tier port holds (the least of any)
//   fleet.decimate_day_ms_single_tier  the same decimation from the single-tier buffers
#pragma once

#include <QString>
#include <array>

namespace tipscope::model {
class Telemetry;
}

namespace tipscope::bench {

inline constexpr int kFleetPorts = 4;

// Samples per second of each port (index 0..3) and of the feeder (index 4).
using ChannelRates = std::array<double, kFleetPorts + 1>;

// "port1".."port4", "feeder": how a telemetry key of the channel ends.
[[nodiscard]] QString fleetChannelName(int index);

// Samples appended so far to each channel's buffers, summed over every device of `telemetry`.
[[nodiscard]] std::array<qint64, kFleetPorts + 1> channelSamples(const model::Telemetry &telemetry);

void printDayMemory(const ChannelRates &rates, int stations, qint64 hours);

} // namespace tipscope::bench
