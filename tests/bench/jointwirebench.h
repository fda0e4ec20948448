// runJointWireBench: how well joints are found and measured through the wire, in every front
// end, for `tipscope-bench joints --wire`.
//
// For each shape set (--sets, default demo,varied,slow: sim::JointShapeSet) a simulated DME
// station (four ports) makes random joints on every port, about --per-minute N a minute on each
// (default 12, seeded by --seed S), on a line paced at 19200 baud and handed over in 8 ms chunks
// like the demo's USB adapter. Each set is measured, side by side in one run and for --minutes M
// (default 10), through each front end (--frontends, default all):
//   core        the session's own classes in this process: the real request queue and
//               PollScheduler with the four ports on screen, telemetry and the JointWatcher
//   core_fixed  the same with adaptive sampling off, for comparison
//   cli         a `tipscope-cli monitor --journal J` process with the default options, on its
//               own simulator (tipscope-sim over TCP), its joints read back from the journal
//   cli_5000    the same with `--interval 5000`
//   agent       a `tipscope-agent` process (and a Mosquitto broker) on its own simulator
// and prints, per set and front end, `joints.<set>.<frontend>.<figure>` (jointscore.h): true and
// found joints, precision, recall, the error p50/p95/max and bias of the recoveries given as
// measured, how many were only bounded and the share of those bounds that hold the truth, start
// error p95, dip error p95, and beside it the dip error of an oracle that knew the true tip at the
// same sample instants (from the simulator's truth); for core also the spacing of tip readings
// and the polls a second. Each front end is scored from 15 s after it started (the tips heat up
// and settle first). A benchmark: it asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runJointWireBench(const QStringList &args);

} // namespace tipscope::bench
