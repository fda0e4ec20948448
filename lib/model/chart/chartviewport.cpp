#include "model/chart/chartviewport.h"

#include <cmath>

namespace tipscope::model {

ChartViewport::ChartViewport(QObject *parent)
    : QObject(parent) {}

void ChartViewport::setDataRange(qint64 first, qint64 last) {
    const bool same = m_hasData && first == m_dataStart && last == m_dataEnd;
    m_dataStart = first;
    m_dataEnd = qMax(first, last);
    m_hasData = true;
    if (m_following)
        follow(m_followWindow);
    else if (!same)
        place(m_end, m_window, false); // data left the ring: keep the window over what remains
}

void ChartViewport::setWindowLength(qint64 ms) {
    m_chosenWindow = qBound(kMinWindowMs, ms, kMaxWindowMs);
    m_followWindow = m_chosenWindow;
    // A new length keeps the right edge where it is, so a paused view keeps its end in sight.
    if (m_following)
        follow(m_chosenWindow);
    else
        place(m_end, m_chosenWindow, false);
}

void ChartViewport::setFollowing(bool on) {
    if (on)
        follow(m_window);
    else
        place(m_end, m_window, false);
}

void ChartViewport::reset() {
    follow(m_chosenWindow);
}

void ChartViewport::follow(qint64 window) {
    m_followWindow = window;
    if (!m_hasData) {
        place(m_end, window, true);
        return;
    }
    const qint64 end = m_dataEnd + 1; // +1: the window is half-open
    const qint64 shown = qBound(kMinWindowMs, end - m_dataStart, window);
    place(qMax(end, m_dataStart + shown), shown, true);
}

void ChartViewport::zoom(double factor, qint64 anchorMs) {
    if (!(factor > 0))
        return;
    const qint64 window =
        qBound(kMinWindowMs, qint64(std::llround(double(m_window) * factor)), kMaxWindowMs);
    // The anchor keeps its fraction of the window.
    const double fraction = qBound(0.0, double(m_end - anchorMs) / double(m_window), 1.0);
    const qint64 end = anchorMs + qint64(std::llround(fraction * double(window)));
    place(end, window, false);
}

void ChartViewport::pan(qint64 deltaMs) {
    if (deltaMs != 0)
        place(m_end + deltaMs, m_window, false);
}

void ChartViewport::showRange(qint64 t0, qint64 t1) {
    if (t1 < t0)
        std::swap(t0, t1);
    const qint64 window = qBound(kMinWindowMs, t1 - t0, kMaxWindowMs);
    // A range shorter than the minimum grows around its middle.
    place(t0 + (t1 - t0) / 2 + window / 2, window, false);
}

qint64 ChartViewport::clampEnd(qint64 end, qint64 window) const {
    if (!m_hasData)
        return end;
    // Keep at least a tenth of the window over the data.
    const qint64 keep = window / 10;
    return qBound(m_dataStart + keep, end, m_dataEnd + 1 + window - keep);
}

void ChartViewport::place(qint64 end, qint64 window, bool following) {
    end = following ? end : clampEnd(end, window);
    const bool followChanged = following != m_following;
    if (end == m_end && window == m_window && !followChanged)
        return;
    m_end = end;
    m_window = window;
    m_following = following;
    Q_EMIT changed();
    if (followChanged)
        Q_EMIT followingChanged(following);
}

} // namespace tipscope::model
