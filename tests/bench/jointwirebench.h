// runJointWireBench: how well joints are found and measured through the wire, for
// `tipscope-bench joints --wire`. A simulated DME station (four ports) on a SimLine paced at
// 19200 baud, handed over in 8 ms chunks like the demo's USB adapter, is polled through the real
// request queue by the real PollScheduler with all four ports on screen (the application's
// default intervals, or --live-ms and --status-ms), its readings recorded as telemetry and fed
// to the session's JointWatcher. The simulator makes joints of varied depth (15-100 K) and
// recovery (0.4-3 s) on every port, about --per-minute N a minute on each (default 12, seeded by
// --seed S), for --minutes M (default 10), and reports each with its true values
// (SimLine::jointMade). Two such lines run side by side in the same process and time, the same
// seed: one with adaptive sampling, one without. For each it prints:
//   joints.wire[.adaptive_off].true / .found   joints made (ended before the run did) and found
//   joints.wire[.adaptive_off].precision       found joints that match a true one (same port,
//                                              start within 1 s)
//   joints.wire[.adaptive_off].recall          true joints found
//   joints.wire[.adaptive_off].recovery_error_p50 / _p95 / _max   |measured − true recovery|
//   joints.wire[.adaptive_off].recovery_bias   mean of measured − true recovery
//   joints.wire[.adaptive_off].start_error_p95 |measured − true start|
//   joints.wire[.adaptive_off].tip_period_p50 / _p95   time between tip readings of a port
//   joints.wire[.adaptive_off].polls_per_s
// A benchmark: it asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runJointWireBench(const QStringList &args);

} // namespace tipscope::bench
