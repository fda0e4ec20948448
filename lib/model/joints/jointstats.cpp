#include "jointstats.h"

#include <QDateTime>
#include <QMap>
#include <algorithm>

namespace tipscope::model {

namespace {
qint64 roundBinMs(qint64 maxMs, int maxBins) {
    static constexpr qint64 kWidths[] = {100, 200, 250, 500};
    for (qint64 scale = 1;; scale *= 10)
        for (const qint64 width : kWidths)
            if (maxMs / (width * scale) < maxBins)
                return width * scale;
}

qint64 nearestRankMedian(QList<qint64> values) {
    std::sort(values.begin(), values.end());
    return values.at((values.size() + 1) / 2 - 1);
}
} // namespace

int RecoveryHistogram::maxCount() const {
    return counts.isEmpty() ? 0 : *std::max_element(counts.cbegin(), counts.cend());
}

RecoveryHistogram recoveryHistogram(const QList<JointRow> &rows, int maxBins) {
    RecoveryHistogram h;
    qint64 maxMs = -1;
    for (const JointRow &r : rows) {
        if (r.joint.recoveryMs)
            maxMs = qMax(maxMs, *r.joint.recoveryMs);
        else
            ++h.notRecovered;
    }
    if (maxMs < 0)
        return h;
    h.binMs = roundBinMs(maxMs, qMax(1, maxBins));
    h.counts.fill(0, int(maxMs / h.binMs) + 1);
    for (const JointRow &r : rows)
        if (r.joint.recoveryMs)
            ++h.counts[int(qMax<qint64>(0, *r.joint.recoveryMs) / h.binMs)];
    return h;
}

QList<ToolTrend> dailyRecoveryByTool(const QList<JointRow> &rows) {
    QMap<QString, QMap<QDate, QList<qint64>>> byTool;
    for (const JointRow &r : rows) {
        if (!r.joint.recoveryMs)
            continue;
        const QDate day = QDateTime::fromMSecsSinceEpoch(r.joint.startMs).toLocalTime().date();
        byTool[r.joint.tool][day].append(*r.joint.recoveryMs);
    }
    QList<ToolTrend> trends;
    for (auto tool = byTool.cbegin(); tool != byTool.cend(); ++tool) {
        ToolTrend trend{tool.key(), {}};
        for (auto day = tool->cbegin(); day != tool->cend(); ++day)
            trend.days.append({day.key(), nearestRankMedian(*day), int(day->size())});
        trends.append(trend);
    }
    return trends;
}

} // namespace tipscope::model
