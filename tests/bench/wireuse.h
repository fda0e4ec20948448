// How a line spends its wire while a joint is under way, for `tipscope-bench joints --wire`: a
// joint should have the full wire, most of it spent on the busy ports' tips.
//
// Sampled every kTickMs: the line's answers and bytes since the last tick, and which ports the
// scheduler's rule calls busy; the readings of each tip are counted as they come and charged to
// the tick they fall in. A tick counts as busy when a port was busy at its start, so a joint's
// first and last readings may fall either side; over minutes that evens out.
#pragma once

#include "model/device/stationmodel.h"

#include <QList>
#include <QMap>
#include <QObject>
#include <QTimer>
#include <array>

namespace tipscope::link {
class Line;
}
namespace tipscope::model {
class PollScheduler;
}

namespace tipscope::bench {

struct JointFigure;

class WireUse : public QObject {
public:
    // The wire carries `bytesPerSecond` (baud / 10 for 8N1).
    WireUse(link::Line &line, model::StationModel &station, const model::PollScheduler &scheduler,
            double bytesPerSecond);
    void start();
    void stop() { m_tick.stop(); }
    // busy_wire_ratio: the line's transactions while any port is busy, over what its wire
    // carries at the bytes per transaction measured then; busy_tip_share: the busy ports' tip
    // readings over all transactions then; busy_seconds: how long any port was busy.
    [[nodiscard]] QList<JointFigure> figures() const;
    // Where the busy wire went, largest share first: "tip of a busy port 29 %, ...".
    [[nodiscard]] QString breakdown() const;

    static constexpr int kTickMs = 50;

private:
    void tick();

    link::Line &m_line;
    model::StationModel &m_station;
    const model::PollScheduler &m_scheduler;
    double m_bytesPerSecond;
    QTimer m_tick;
    // Every polled value's readings since the last tick, and while busy in all, by what it is.
    struct Reads {
        QString kind; // a busy port's kind is named at the tick
        int port = 0;
        protocol::Role role = protocol::Role::None;
        qint64 sinceTick = 0;
    };
    QList<Reads> m_reads;
    QMap<QString, qint64> m_busyReadsByKind;
    std::array<bool, 5> m_busy{}; // at the last tick
    qint64 m_lastAnswered = 0;
    qint64 m_lastBytes = 0;
    qint64 m_busyTicks = 0;
    qint64 m_busyAnswered = 0;
    qint64 m_busyBytes = 0;
    qint64 m_busyTipReads = 0;
};

} // namespace tipscope::bench
