// PollScheduler: spends the wire where people look.
//
// Every readable parameter of the devices it is given belongs to a poll class from the catalog:
// live (tip temperature, power, status, setpoint), status (errors, alarms, tool, delays),
// settings, counters, identity. Each class has an interval; live values of ports nobody is
// looking at are polled at the status interval instead. The scheduler is self-clocking: it keeps
// at most maxInFlight polls in the request queue and sends the next only when one finishes, so it
// never offers more load than the wire carries. Due live values go first, but every fourth poll
// goes to another value (errors and status before settings, counters and identity), so a burst
// of settings (a page opening) cannot freeze the live curves and live values cannot starve the
// rest. When the wire cannot
// keep up, values simply update less often; Parameter::achievedRateHz() says how often. Polls use
// the queue's polling and background priorities, so user writes and reads always go first. A line
// that is not open pauses polling for a second at a time.
#pragma once

#include "parameter.h"

#include <QElapsedTimer>
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
    // Ports whose live values are polled at the live interval (the others at the status one).
    void setVisiblePorts(DeviceModel *device, const QSet<int> &ports);
    // Polls a class of a device once now (a page opened, a write finished).
    void requestRefresh(DeviceModel *device, PollClass pollClass);
    void setMaxInFlight(int n) { m_maxInFlight = qMax(1, n); }

    void start();
    void stop();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] qint64 pollsDone() const { return m_done; }

private:
    struct Item {
        QPointer<Parameter> parameter;
        DeviceModel *device = nullptr;
        PollClass pollClass = PollClass::None;
        int port = 0;
        qint64 dueMs = 0;
        bool inFlight = false;
    };

    void pump();
    [[nodiscard]] int effectiveInterval(const Item &item) const;
    [[nodiscard]] qint64 nowMs() const { return m_clock.elapsed(); }
    void armWake();

    std::vector<Item> m_items;
    QMap<DeviceModel *, QSet<int>> m_visible;
    int m_intervals[5] = {250, 2000, 0, 60000, 0};
    int m_maxInFlight = 2;
    int m_inFlight = 0;
    int m_slot = 0;
    bool m_running = false;
    qint64 m_holdUntilMs = 0;
    qint64 m_done = 0;
    QElapsedTimer m_clock;
    QTimer m_wake;
};

} // namespace tipscope::model
