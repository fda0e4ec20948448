// runFleetBench: whether a day of a fleet's telemetry fits in memory, for
// `tipscope-bench fleet-memory`.
//
// The demo line runs for --seconds (default 30) with every port shown, as the Charts page polls
// them, and each port's and the feeder's samples per second are counted (--hz R skips the demo
// and takes R for every channel); printed as fleet.demo_port<N>_hz and fleet.demo_feeder_hz. At
// those rates printDayMemory() (fleetday.h) fills --hours (24) of --stations (32) stations,
// tiered and single-tier, and prints the memory figures.
// A benchmark: it asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runFleetBench(const QStringList &args);

} // namespace tipscope::bench
