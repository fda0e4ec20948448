// TelemetryGaps: the stretches of one history where nothing was measured, recorded as data.
//
// A history has no sample while the line is down, while a device does not answer or after the
// user disconnected; the sample after such a stretch must not be joined to the one before it.
// A gap opens when the writer says continuity broke (open()) and closes at the next sample
// (close()); a gap that is still open runs to "now". Readers ask whether a time falls in a gap
// (a crosshair shows nothing there), which gaps overlap a window (a chart breaks its curve, an
// export writes them) and where the continuous stretches of a window are (a measurement never
// spans a gap). Gaps are kept in time order and never overlap; opening while one is open keeps
// the first. Bounded like the samples: gaps that end before the oldest sample held are dropped.
#pragma once

#include <QList>
#include <QString>
#include <QtGlobal>
#include <deque>
#include <optional>

namespace tipscope::model {

struct TelemetryGap {
    enum class Cause { LineDown, NoAnswer, Disconnected };

    qint64 startMs = 0;
    std::optional<qint64> endMs; // the first sample after it; nullopt while it is still open
    Cause cause = Cause::LineDown;

    [[nodiscard]] bool contains(qint64 timeMs) const {
        return timeMs >= startMs && (!endMs || timeMs < *endMs);
    }
    // Stable English token for files ("line-down", "no-answer", "disconnected").
    [[nodiscard]] static QString causeToken(Cause cause);
    [[nodiscard]] static std::optional<Cause> causeFromToken(const QString &token);
};

class TelemetryGaps {
public:
    // Continuity broke at `timeMs` (clamped to after `lastSampleMs`); no-op while a gap is open.
    void open(qint64 timeMs, qint64 lastSampleMs, TelemetryGap::Cause cause);
    // A sample arrived at `timeMs`: the open gap, if any, ends there.
    void close(qint64 timeMs);
    // Drops gaps that ended before `oldestSampleMs`.
    void trim(qint64 oldestSampleMs);

    [[nodiscard]] bool isOpen() const { return !m_gaps.empty() && !m_gaps.back().endMs; }
    [[nodiscard]] qsizetype size() const { return qsizetype(m_gaps.size()); }
    // The gap holding `timeMs`, if any.
    [[nodiscard]] std::optional<TelemetryGap> at(qint64 timeMs) const;
    // The gaps overlapping [t0, t1), oldest first.
    [[nodiscard]] QList<TelemetryGap> within(qint64 t0, qint64 t1) const;
    // [t0, t1) cut at every gap: the half-open stretches between them, oldest first.
    [[nodiscard]] QList<QPair<qint64, qint64>> continuousStretches(qint64 t0, qint64 t1) const;

private:
    std::deque<TelemetryGap> m_gaps;
};

} // namespace tipscope::model
