// DemoActivity: what a station in use does, played on the demo line so its curves show what the
// charts are for. Port 1 makes a joint every 15 s (a 50 K dip, back within the band after 1.5 s,
// shaped by JointShape); port 2 works for 40 s, rests in the stand for 30 s (where the demo's
// tool sleeps at once) and is picked up again (a wake and its heat-up); the feeder feeds for 2 s
// every 20 s. Ports 3 and 4 are left alone for what tests and people set on them. A port without a
// tool or in error, and a feeder in error, are skipped; a rest or a feed it did not start is left
// to whoever started it. It runs on the devices' simulated time, so it is as repeatable as they
// are.
#pragma once

#include <QtGlobal>

namespace tipscope::sim {

class SimFeeder;
class SimStation;

class DemoActivity {
public:
    static constexpr int kJointEveryMs = 15'000;
    static constexpr int kJointOffsetMs = 8'000;
    static constexpr int kJointDepthK = 50;
    static constexpr int kJointRecoveryMs = 1500;
    static constexpr int kRestCycleMs = 70'000;
    static constexpr int kRestStartMs = 40'000; // in the cycle; the rest lasts until it ends
    static constexpr int kFeedEveryMs = 20'000;
    static constexpr int kFeedOffsetMs = 5'000;
    static constexpr int kFeedMs = 2'000;

    // Either may be nullptr. They must outlive the activity (the line owns all three).
    DemoActivity(SimStation *station, SimFeeder *feeder);

    void advance(int ms);

private:
    // Whether `offset + k * period` (k >= 0) lies in (m_ms - ms, m_ms].
    [[nodiscard]] bool passed(int ms, qint64 offset, qint64 period) const;
    [[nodiscard]] bool portInUse(int port) const;

    SimStation *m_station;
    SimFeeder *m_feeder;
    qint64 m_ms = 0;
    // What the activity itself started: it ends only that, never a rest or a feed someone else
    // asked for on the line.
    bool m_resting = false;
    bool m_feeding = false;
};

} // namespace tipscope::sim
