// PollScheduler: spends the wire where people look.
//
// Every readable parameter of the devices it is given belongs to a poll class from the catalog:
// live (tip temperature, power, status, setpoint), status (errors, alarms, tool, delays),
// settings, counters, identity. Each class has an interval; live values of ports nobody is
// looking at are polled at the status interval instead, except their tip temperature and power,
// which every port's joints are measured from whatever page is shown. The scheduler is
// self-clocking: it keeps at most maxInFlight polls in the request queue and sends the next only
// when one finishes, so it never offers more load than the wire carries. Due live values go first,
// but every second poll (every fourth while a port is in a joint) goes to another value (errors and
// status before settings, counters and identity, but every second of those turns the other way
// round), so a burst of settings (a page opening) cannot freeze the live curves, and neither live
// values nor the many status values can starve the rest. When the wire cannot keep up, values
// simply update less often; Parameter::achievedRateHz() says how often. Polls use the queue's
// polling priority (an early read the background one), so user writes and reads always go first;
// among polls the turns above decide. A line that is not open pauses polling for a second at a
// time; a value the device refuses is asked for again only once a minute.
//
// Adaptive sampling (setAdaptive(), on by default) spends the wire on joints. A working port is
// busy while its last tip reading is more than kBusyBelowK from its setpoint or its power is
// above kBusyPowerShare of full scale; a resting one (stand, sleep, hibernation, cooling, no tool,
// a port error) only while its tip climbs kWakeRiseK above its lowest reading since it rested, a
// wake, a tool put back or a fault cleared that its readings have not told yet. Every port's tip
// is due kWatchFactor times as often as the live interval says (never more often than
// kFastestMs), busy or not: a joint's start can be timed no finer than the last reading before
// it, and a return's fit is limited by the readings' wobble long before a busy tip's rate
// (docs/joints.md, "What limits the accuracy"). A busy port's power is due at the live interval,
// and a port turning busy has its tip and power polled at once, and its status, setpoint, tool
// and error too (a tip leaving its band may be a tool put in its stand, asleep or taken out, or a
// fault: an event to stamp when the tip shows it). While any port is busy the line fills its wire
// (below) and what it has to spare goes to the tips: for kFallWatchMs to a port that has just
// turned busy (its fall and lowest point), then to every port's alike, so a joint and the next
// one's start are read as finely as the wire allows; the values that can wait a joint out (the
// countdown to sleep, the transistor's temperature) are due kRestFactor times less often
// meanwhile. Values that rarely change are due kRestFactor
// times less often: a port's status among the live values, its setpoint and its connected tool; so
// is a resting port's power, which is not needed to see a joint begin. Errors and alarms keep their
// interval: a fault is never reported later for it. When the wire is full, the due live value
// longest overdue for its own interval goes first, so each gets the wire in proportion to its rate:
// a recovery is sampled finely while the resting ports keep their turns. Off, every value keeps its
// class's interval and the earliest due goes first.
//
// Filling the wire (setFillWire(), off by default; a Workspace turns it on; always while a port is
// busy, adaptive) polls a line at the rate its wire carries rather than at its intervals: when a
// slot is free and nothing is due, it goes to the live value furthest along its own interval, so
// every live value is read as often as the wire allows, each in proportion to its rate (a tip
// still twice as often as its live interval says relative to its power, and so on), but for the
// tips, which take every such slot while a joint is under way. Only live values are read early:
// errors, settings, counters and identity keep their intervals.
#pragma once

#include "model/device/parameter.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QTimer>
#include <vector>

namespace tipscope::model {

class DeviceModel;

enum class PollClass { Live, Status, Settings, Counter, Identity, None };
[[nodiscard]] PollClass pollClassOf(const protocol::CommandSpec &spec);

class PollScheduler : public QObject {
    Q_OBJECT
public:
    explicit PollScheduler(QObject *parent = nullptr);

    void addDevice(DeviceModel *device);
    void removeDevice(DeviceModel *device);
    // 0 means "once, then only on request".
    void setInterval(PollClass pollClass, int ms);
    [[nodiscard]] int interval(PollClass pollClass) const;
    // Ports whose live values are polled at the live interval (the others at the status one,
    // but for their tip temperature and power).
    void setVisiblePorts(DeviceModel *device, const QSet<int> &ports);
    // Polls a class of a device once now (a page opened, a write finished).
    void requestRefresh(DeviceModel *device, PollClass pollClass);
    void setMaxInFlight(int n) { m_maxInFlight = qMax(1, n); }
    void setAdaptive(bool on);
    void setFillWire(bool on);
    [[nodiscard]] bool fillsWire() const { return m_fillWire; }
    [[nodiscard]] bool isAdaptive() const { return m_adaptive; }
    // Whether the port's last readings say it is in a joint (the adaptive rule above).
    [[nodiscard]] bool isBusy(DeviceModel *device, int port) const;

    static constexpr int kBusyBelowK = 5;
    // A resting port (stand, sleep, ...) is busy once its tip is this far above its lowest
    // reading since it rested: a wake, before the status says so.
    static constexpr int kWakeRiseK = 8;
    static constexpr double kBusyPowerShare = 0.6;
    static constexpr int kWatchFactor = 2;
    // How long a port that has just turned busy takes the wire's spare first: a joint's fall and
    // its lowest point (the drops measured take 50 to 400 ms).
    static constexpr int kFallWatchMs = 500;
    static constexpr int kRestFactor = 4;
    static constexpr int kFastestMs = 25;

    void start();
    void stop();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] qint64 pollsDone() const { return m_done; }

private:
    struct Item {
        QPointer<Parameter> parameter;
        Parameter *raw = nullptr; // the same, to find the item fast; never dereferenced
        DeviceModel *device = nullptr;
        PollClass pollClass = PollClass::None;
        int port = 0;
        protocol::Role role = protocol::Role::None;
        qint64 dueMs = 0;
        bool inFlight = false;
        qint64 polledMs = 0; // when its last poll finished
        qint64 sentMs = 0;   // when its last poll was sent
        int interval = 0;    // effectiveInterval(), kept current by updateIntervals()
        bool first = false;  // ahead of the others of its kind until sent (askWhy())
    };

    void pump();
    // The interval the item is polled at now. Cached: choosing a poll compares every item, and
    // working it out each time (the port's visibility, whether it is in a joint) was most of the
    // scheduler's cost at a full wire.
    [[nodiscard]] static int effectiveInterval(const Item &item) { return item.interval; }
    [[nodiscard]] int computeInterval(const Item &item) const;
    // After what the intervals depend on changed: of a device's items (all devices' when null),
    // of one port's when port >= 0.
    void updateIntervals(const DeviceModel *device = nullptr, int port = -1);
    [[nodiscard]] int adaptedInterval(const Item &item, int interval) const;
    // A busy port's tip temperature or power, while adaptive.
    [[nodiscard]] bool inJoint(const Item &item) const;
    // The order among due live values, lowest first: their due time; adaptive, how long they
    // are overdue for their interval.
    [[nodiscard]] double urgency(const Item &item, qint64 now) const;
    // Filling the wire: the live value furthest along its interval, not yet due; null if none.
    [[nodiscard]] Item *furthestAlong(qint64 now);
    // After a reading of a value with role `read`: a port that has just turned busy gets its tip
    // and power due now, its status and setpoint at once.
    void followBusy(DeviceModel *device, int port, protocol::Role read, qint64 now);
    void askWhy(DeviceModel *device, int port, qint64 now);
    [[nodiscard]] qint64 nowMs() const { return m_clock.elapsed(); }
    void armWake();

    std::vector<Item> m_items;
    QMap<DeviceModel *, QSet<int>> m_visible;
    int m_intervals[5] = {250, 2000, 0, 60000, 0};
    int m_maxInFlight = 2;
    int m_inFlight = 0;
    int m_slot = 0;
    int m_othersTurns = 0; // the turns of the rest that went to one of them
    bool m_running = false;
    bool m_adaptive = true;
    bool m_fillWire = false;
    QHash<QPair<DeviceModel *, int>, qint64> m_busy;    // busy ports: when each turned busy
    QHash<QPair<DeviceModel *, int>, qint64> m_restLow; // a resting port's lowest tip
    QSet<QPair<DeviceModel *, int>> m_resting;          // ports that rest (stand, no tool, ...)
    qint64 m_holdUntilMs = 0;
    qint64 m_done = 0;
    QElapsedTimer m_clock;
    QTimer m_wake;
};

} // namespace tipscope::model
