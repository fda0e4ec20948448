// EventTally: the events this process's main thread delivers while it lives, by kind: timer
// events (each a timer that came due), socket notifications (each a wake-up for bytes on a
// line), queued calls and posted work, and paints. Installed on the application object, it
// sees every event of the main thread before any object does.
#pragma once

#include <QEvent>
#include <QObject>
#include <array>

namespace tipscope::bench {

class EventTally : public QObject {
public:
    EventTally();
    ~EventTally() override;
    EventTally(const EventTally &) = delete;
    EventTally &operator=(const EventTally &) = delete;

    // Of the kinds Qt numbers below 256 (every kind a benchmark asks for).
    [[nodiscard]] qint64 count(QEvent::Type type) const {
        return size_t(type) < m_counts.size() ? m_counts[size_t(type)] : 0;
    }
    [[nodiscard]] qint64 total() const { return m_total; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    std::array<qint64, 256> m_counts{}; // an array: the tally must cost next to nothing
    qint64 m_total = 0;
};

} // namespace tipscope::bench
