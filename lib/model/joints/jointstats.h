// Recovery-time statistics over the joints a view lists: a histogram (how the recoveries spread)
// and a per-tool trend by day (is a tip wearing out: its daily median recovery creeping up).
//
// Only joints that recovered have a recovery time; the others are counted apart
// (notRecovered), never as zero. Days are local calendar days of the joints' starts. The median
// is the nearest-rank median, as the journal's recoveryByPort computes it.
#pragma once

#include "model/joints/jointtable.h"

#include <QDate>
#include <QList>
#include <QString>

namespace tipscope::model {

struct RecoveryHistogram {
    qint64 binMs = 0;  // the width of a bin; bin i holds [i·binMs, (i+1)·binMs)
    QList<int> counts; // empty when no joint recovered
    int notRecovered = 0;
    [[nodiscard]] int maxCount() const;
};

// Bins of a round width (0.1, 0.2, 0.25, 0.5, 1, 2, 2.5, 5 s, ...) chosen so there are at most
// `maxBins`.
[[nodiscard]] RecoveryHistogram recoveryHistogram(const QList<JointRow> &rows, int maxBins = 20);

struct DailyRecovery {
    QDate day;
    qint64 medianMs = 0;
    int joints = 0; // that recovered, on that day
};

struct ToolTrend {
    QString tool;
    QList<DailyRecovery> days; // oldest first; days without a recovered joint are absent
};

// Tools in name order; a tool none of whose joints recovered is absent.
[[nodiscard]] QList<ToolTrend> dailyRecoveryByTool(const QList<JointRow> &rows);

} // namespace tipscope::model
