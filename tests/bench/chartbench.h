// runChartBench: what the charts cost, for `tipscope-bench chart` (needs a QApplication; the
// dispatcher makes one, offscreen unless QT_QPA_PLATFORM says otherwise).
//
// Fills the telemetry of four ports with a day at 10 Hz (864,000 samples per series), then
// prints, one "name: value unit" line each:
//   telemetry.bytes_per_sample      telemetry allocation per sample per series
//   telemetry.memory_mb             the four buffers' allocation
//   chart.redraw_full_ms            one update of a 1920 px chart over the whole day: decimation
//                                   of 12 series (tip, setpoint, power of 4 ports), one replace()
//                                   each, layout and a full paint; median of several runs
//   chart.decimate_full_ms          the part of it spent in the telemetry's decimation
//   chart.redraw_1min_ms            the same over one minute in the middle of the day (and
//                                   chart.decimate_1min_ms)
//   chart.points_full               points handed to Qt Charts by one full-day update
//   chart.naive_redraw_full_ms      the same update with every sample handed to QLineSeries
//                                   (10.4 million points, one replace() per series); one run
//   chart.speedup                   naive / decimated, full day
//   memory.peak_rss_*_mb            peak resident set at start, after filling the telemetry,
//                                   after the decimated chart and after the naive one
//   gui.cpu_percent                 CPU of this process (GUI thread and all) over --seconds (60)
//                                   with the demo line live, four ports polled, the Charts page
//                                   shown; percent of one core. The demo's simulator and line
//                                   run in this process too, so also:
//   gui.cpu_overview_percent        the same with the Overview page (also all four ports) shown
//   gui.chart_cpu_percent           the difference: what the chart adds
//   gui.redraws_per_s               chart redraws per second while it is shown
// Options: --seconds N (each CPU run), --no-gui (skip them), --gui-only (only them),
// --no-baseline (skip the Overview run). A benchmark: it asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runChartBench(const QStringList &args);

} // namespace tipscope::bench
