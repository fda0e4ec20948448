// runGuiBench: whether any view of the window slows the wire, for `tipscope-bench gui`.
//
// Starts one `tipscope-sim --tcp 127.0.0.1:0 --pace 19200` DME making joints of the varied shape
// set on every port (the busiest a line gets), opens it in the real main window at 1280x720 on
// the offscreen platform (or the one QT_QPA_PLATFORM names), and shows each view in turn for
// --seconds (default 20): every page, and the Charts page with its ports overlaid and with one
// pane per port. For each view it prints
//   gui.<view>.tx_per_s          answered transactions a second while the view was shown
//   gui.<view>.wire_limit_tx_per_s  what the paced wire carries at the line's own frame sizes
//   gui.<view>.rate_ratio        the two side by side (a view that slows the wire shows here)
//   gui.<view>.cpu_percent       this process's user + system CPU, % of one core
//   gui.<view>.timeouts          requests that went unanswered meanwhile
// and gui.worst_rate_ratio, the lowest ratio of them all (goal: >= 0.95 for every view). A
// benchmark: it asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runGuiBench(const QStringList &args);

} // namespace tipscope::bench
