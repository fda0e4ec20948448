#include "model/telemetry/telemetrygaps.h"

#include <algorithm>

namespace tipscope::model {

namespace {
struct CauseToken {
    TelemetryGap::Cause cause;
    const char *token;
};
constexpr CauseToken kTokens[] = {{TelemetryGap::Cause::LineDown, "line-down"},
                                  {TelemetryGap::Cause::NoAnswer, "no-answer"},
                                  {TelemetryGap::Cause::Disconnected, "disconnected"}};
} // namespace

QString TelemetryGap::causeToken(Cause cause) {
    for (const CauseToken &t : kTokens)
        if (t.cause == cause)
            return QLatin1String(t.token);
    return {};
}

std::optional<TelemetryGap::Cause> TelemetryGap::causeFromToken(const QString &token) {
    for (const CauseToken &t : kTokens)
        if (token == QLatin1String(t.token))
            return t.cause;
    return std::nullopt;
}

void TelemetryGaps::open(qint64 timeMs, qint64 lastSampleMs, TelemetryGap::Cause cause) {
    if (isOpen())
        return;
    // The last sample stays readable: the gap starts after it.
    m_gaps.push_back({qMax(timeMs, lastSampleMs + 1), std::nullopt, cause});
}

void TelemetryGaps::close(qint64 timeMs) {
    if (isOpen())
        m_gaps.back().endMs = qMax(timeMs, m_gaps.back().startMs);
}

void TelemetryGaps::trim(qint64 oldestSampleMs) {
    while (!m_gaps.empty() && m_gaps.front().endMs && *m_gaps.front().endMs < oldestSampleMs)
        m_gaps.pop_front();
}

std::optional<TelemetryGap> TelemetryGaps::at(qint64 timeMs) const {
    // The last gap starting at or before the time is the only one that can hold it.
    auto it = std::upper_bound(m_gaps.begin(), m_gaps.end(), timeMs,
                               [](qint64 t, const TelemetryGap &g) { return t < g.startMs; });
    if (it == m_gaps.begin())
        return std::nullopt;
    --it;
    if (it->contains(timeMs))
        return *it;
    return std::nullopt;
}

QList<TelemetryGap> TelemetryGaps::within(qint64 t0, qint64 t1) const {
    QList<TelemetryGap> out;
    auto it =
        std::lower_bound(m_gaps.begin(), m_gaps.end(), t0,
                         [](const TelemetryGap &g, qint64 t) { return g.endMs && *g.endMs <= t; });
    for (; it != m_gaps.end() && it->startMs < t1; ++it)
        out.append(*it);
    return out;
}

QList<QPair<qint64, qint64>> TelemetryGaps::continuousStretches(qint64 t0, qint64 t1) const {
    QList<QPair<qint64, qint64>> out;
    qint64 from = t0;
    for (const TelemetryGap &g : within(t0, t1)) {
        if (g.startMs > from)
            out.append({from, g.startMs});
        if (!g.endMs)
            return out;
        from = qMax(from, *g.endMs);
    }
    if (from < t1)
        out.append({from, t1});
    return out;
}

} // namespace tipscope::model
