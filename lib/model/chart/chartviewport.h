// ChartViewport: which time window the charts show, and how people move it.
//
// The window is [start(), end()), its length between kMinWindowMs (30 s) and kMaxWindowMs
// (24 h). Following, the window ends just after the newest sample and moves with the data;
// while there is less data than the chosen length, the window spans the data (at least 30 s,
// starting at the first sample), so the first minutes fill the view as on a scope instead of
// a sliver at the right of an empty window;
// zooming, panning or choosing a range by hand stops following (the person is looking at
// something), and setFollowing(true) or reset() resumes it. Zoom keeps the instant under the
// cursor where it is. Panning stops at the data: the window keeps some overlap with
// [dataStart, dataEnd] so the charts never scroll off into emptiness.
//
// Plain state, no widgets: the page feeds it the data's extent and the chart's gestures, and
// redraws when changed() says the window moved.
#pragma once

#include <QObject>

namespace tipscope::model {

class ChartViewport : public QObject {
    Q_OBJECT
public:
    static constexpr qint64 kMinWindowMs = 30'000;
    static constexpr qint64 kMaxWindowMs = 24 * 3600'000LL;
    static constexpr qint64 kDefaultWindowMs = 5 * 60'000;

    explicit ChartViewport(QObject *parent = nullptr);

    [[nodiscard]] qint64 start() const { return m_end - m_window; }
    [[nodiscard]] qint64 end() const { return m_end; }
    [[nodiscard]] qint64 windowMs() const { return m_window; }
    // The length the window is meant to have: while following data shorter than it, the window
    // grows towards it; otherwise windowMs(). The toolbar shows this one.
    [[nodiscard]] qint64 targetWindowMs() const { return m_following ? m_followWindow : m_window; }
    [[nodiscard]] bool isFollowing() const { return m_following; }
    [[nodiscard]] qint64 dataStart() const { return m_dataStart; }
    [[nodiscard]] qint64 dataEnd() const { return m_dataEnd; }

    // The extent of the data shown, [first, last] in ms; a following window moves to it.
    void setDataRange(qint64 first, qint64 last);
    // The window length chosen in the toolbar; it becomes the length reset() returns to.
    void setWindowLength(qint64 ms);
    void setFollowing(bool on);
    // Back to the chosen length, following the newest data.
    void reset();
    // `factor` < 1 zooms in; `anchorMs` stays at the same place in the window.
    void zoom(double factor, qint64 anchorMs);
    void pan(qint64 deltaMs);
    // A range picked with the rubber band (or typed); clamped to the allowed lengths.
    void showRange(qint64 t0, qint64 t1);

Q_SIGNALS:
    void changed();
    void followingChanged(bool following);

private:
    void place(qint64 end, qint64 window, bool following);
    [[nodiscard]] qint64 clampEnd(qint64 end, qint64 window) const;
    // Following: the data's end, and a window no longer than the data (see the class comment).
    void follow(qint64 window);

    qint64 m_window = kDefaultWindowMs;
    qint64 m_chosenWindow = kDefaultWindowMs;
    qint64 m_followWindow = kDefaultWindowMs;
    qint64 m_end = 0;
    qint64 m_dataStart = 0;
    qint64 m_dataEnd = 0;
    bool m_hasData = false;
    bool m_following = true;
};

} // namespace tipscope::model
