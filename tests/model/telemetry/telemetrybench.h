// runTelemetryBench: what the telemetry store costs at its design load, for tipscope-bench.
//
// Fills four port buffers of four series ("tip", "setpoint", "power", "status") with a day at
// 10 Hz (864,000 samples each), then prints, one "name: value unit" line each:
//   telemetry.bytes_per_sample       real allocation per sample per series
//   telemetry.decimate_full_1920_ms  one decimate() per series and port over the whole day at
//                                    1920 buckets (16 calls), median of several runs
//   telemetry.decimate_1min_1920_ms  the same over one minute in the middle of the day
//   telemetry.append_ns              mean cost of one append() of four values
// About 60 MB and a second or two of CPU. A benchmark, not a test: it asserts nothing.
#pragma once

class QTextStream;

namespace tipscope::bench {

void runTelemetryBench(QTextStream &out);

} // namespace tipscope::bench
