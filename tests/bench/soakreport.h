// What a soak run measured, and how it is printed and judged.
//
// Soak fills a SoakResult as it goes; printSoakReport() prints every figure as one
// "soak.name: value unit" line (the format of every tipscope-bench figure) and the verdict. The
// run passes only if no write was lost, reported twice or unsolicited, no value was refused
// before sending and every write was started, the device never held (after any write, or at the
// end for any stored setting) a value that the ledger cannot explain, nothing is left pending,
// and the line came back after every unplug.
#pragma once

#include "soakfaults.h"
#include "soakwriter.h"

#include "link/linkstats.h"

namespace tipscope::bench {

struct SoakUnplug {
    qint64 detectMs = -1;   // "unplug" done -> the line reports it lost (-1: never)
    qint64 recoveryMs = -1; // "plug" done -> the first answer on the reopened line (-1: never)
};

struct SoakResult {
    double seconds = 0;
    link::LinkStats link;
    int lineReconnects = 0;
    qint64 polls = 0;
    SimStats sim;
    qint64 nakInjected = 0, delayInjected = 0;
    int nakWindows = 0, delayWindows = 0;
    WriteTally writes;
    int lost = 0;
    int unexpected = 0, fromFailedWrite = 0, unreadable = 0, codes = 0;
    int pendingAfterDrain = -1, pendingAtEnd = -1;
    qint64 rssStartKiB = -1, rssEndKiB = -1, rssPeakKiB = -1, simRssStartKiB = -1,
           simRssEndKiB = -1;
    QList<SoakUnplug> unplugs;
};

// Prints the figures; returns whether the run passed.
bool printSoakReport(const SoakResult &r);

} // namespace tipscope::bench
