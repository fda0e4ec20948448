#include "pollscheduler.h"

#include "model/device/devicemodel.h"
#include "model/device/portmodel.h"

#include <limits>

namespace tipscope::model {

using namespace tipscope::link;

namespace {
constexpr qint64 kNever = std::numeric_limits<qint64>::max() / 2;
constexpr int kLineDownHoldMs = 1000;
// A value the device refused (a station without that reading) is asked for again this rarely:
// the answer is most likely the same, and the wire is better spent on what it can give.
constexpr int kRefusedRetryMs = 60'000;
// A busy tip read early is sent no more often than this: a 19200-baud transaction takes about
// 14 ms, so a station's line never meets it, while a line with no wire time (the demo's unpaced
// one) would otherwise read one tip thousands of times a second and flood its history.
constexpr qint64 kSpareGapMs = 10;
} // namespace

PollClass pollClassOf(const protocol::CommandSpec &spec) {
    static const QMap<QString, PollClass> classes = {
        {QStringLiteral("live"), PollClass::Live},
        {QStringLiteral("status"), PollClass::Status},
        {QStringLiteral("settings"), PollClass::Settings},
        {QStringLiteral("counter"), PollClass::Counter},
        {QStringLiteral("identity"), PollClass::Identity}};
    return classes.value(spec.poll, PollClass::None);
}

PollScheduler::PollScheduler(QObject *parent)
    : QObject(parent) {
    m_clock.start();
    m_wake.setSingleShot(true);
    connect(&m_wake, &QTimer::timeout, this, &PollScheduler::pump);
}

void PollScheduler::addDevice(DeviceModel *device) {
    for (Parameter *p : device->parameters()) {
        const PollClass c = p->isReadable() ? pollClassOf(p->meta()) : PollClass::None;
        if (c == PollClass::None)
            continue;
        m_items.push_back({p, p, device, c, p->meta().usesPort() ? p->spec().port : 0,
                           p->meta().role, nowMs(), false, 0, 0});
    }
    updateIntervals(device);
    connect(device, &QObject::destroyed, this, [this, device] { removeDevice(device); });
    if (m_running)
        pump();
}

void PollScheduler::removeDevice(DeviceModel *device) {
    // A device deleted with polls in flight takes their replies along: they never finish, so
    // their slots are given back here or polling would stall after a reconnect.
    for (const Item &i : m_items)
        if (i.device == device && i.inFlight)
            --m_inFlight;
    m_items.erase(std::remove_if(m_items.begin(), m_items.end(),
                                 [device](const Item &i) { return i.device == device; }),
                  m_items.end());
    m_visible.remove(device);
    for (auto it = m_busy.begin(); it != m_busy.end();)
        it = it.key().first == device ? m_busy.erase(it) : std::next(it);
    for (auto it = m_restLow.begin(); it != m_restLow.end();)
        it = it.key().first == device ? m_restLow.erase(it) : std::next(it);
    for (auto it = m_resting.begin(); it != m_resting.end();)
        it = it->first == device ? m_resting.erase(it) : std::next(it);
}

void PollScheduler::setInterval(PollClass c, int ms) {
    if (c == PollClass::None)
        return;
    m_intervals[int(c)] = qMax(0, ms);
    updateIntervals();
    for (Item &i : m_items)
        if (i.pollClass == c && !i.inFlight)
            i.dueMs = qMin(i.dueMs, nowMs() + effectiveInterval(i));
    if (m_running)
        pump();
}

int PollScheduler::interval(PollClass c) const {
    return c == PollClass::None ? 0 : m_intervals[int(c)];
}

void PollScheduler::setVisiblePorts(DeviceModel *device, const QSet<int> &ports) {
    m_visible.insert(device, ports);
    updateIntervals(device);
    for (Item &i : m_items)
        if (i.device == device && i.pollClass == PollClass::Live && ports.contains(i.port) &&
            !i.inFlight)
            i.dueMs = qMin(i.dueMs, nowMs());
    if (m_running)
        pump();
}

void PollScheduler::requestRefresh(DeviceModel *device, PollClass c) {
    for (Item &i : m_items)
        if (i.device == device && i.pollClass == c && !i.inFlight)
            i.dueMs = nowMs();
    if (m_running)
        pump();
}

void PollScheduler::updateIntervals(const DeviceModel *device, int port) {
    for (Item &i : m_items)
        if ((!device || i.device == device) && (port < 0 || i.port == port))
            i.interval = computeInterval(i);
}

int PollScheduler::computeInterval(const Item &i) const {
    // A port nobody looks at keeps its tip and power at the live interval all the same: its
    // joints are measured from them, and a joint's figures must not depend on the page shown.
    const bool measuresJoints =
        i.role == protocol::Role::TipTemperature || i.role == protocol::Role::Power;
    const int iv = i.pollClass == PollClass::Live && i.port > 0 && !measuresJoints &&
                           !m_visible.value(i.device).contains(i.port)
                       ? m_intervals[int(PollClass::Status)]
                       : m_intervals[int(i.pollClass)];
    return m_adaptive && iv > 0 ? adaptedInterval(i, iv) : iv;
}

int PollScheduler::adaptedInterval(const Item &i, int iv) const {
    using protocol::Role;
    if (i.pollClass == PollClass::Status) {
        // While a joint is under way the wire is the joint's: a countdown to sleep (which the
        // joint restarts anyway) and a transistor's temperature can wait; faults cannot.
        const bool aside = i.role == Role::TimeToNextMode || i.role == Role::TransistorTemperature;
        return i.role == Role::Setpoint || i.role == Role::ConnectedTool ||
                       (aside && !m_busy.isEmpty())
                   ? iv * kRestFactor
                   : iv;
    }
    if (i.pollClass != PollClass::Live || i.port == 0)
        return iv;
    if (i.role == Role::Status)
        return iv * kRestFactor;
    // Every port's tip alike, busy or not: a joint's start is timed by the last reading before
    // it, and the return's fit is limited by the readings' wobble, not by a busy tip's rate.
    if (i.role == Role::TipTemperature)
        return qMax(kFastestMs, iv / kWatchFactor);
    if (inJoint(i)) // a busy port's power sums the joint's heat
        return iv;
    if (i.role == Role::Power) // a resting port's: not needed to see a joint begin
        return iv * kRestFactor;
    return iv;
}

bool PollScheduler::inJoint(const Item &i) const {
    return m_adaptive && i.port > 0 &&
           (i.role == protocol::Role::TipTemperature || i.role == protocol::Role::Power) &&
           m_busy.contains({i.device, i.port});
}

// When the wire is full every live value is overdue. By due time, the most overdue would go
// first, which evens the rates out whatever the intervals; adaptive, the value longest overdue
// for its own interval goes first, so each value gets the wire in proportion to its rate and a
// port in a joint keeps its finer readings while the resting ports still get their turn.
double PollScheduler::urgency(const Item &i, qint64 now) const {
    const int iv = m_adaptive ? effectiveInterval(i) : 0;
    return iv > 0 ? -double(now - i.polledMs) / iv : double(i.dueMs);
}

void PollScheduler::setAdaptive(bool on) {
    m_adaptive = on;
    m_busy.clear();
    updateIntervals();
    const qint64 now = nowMs();
    for (Item &i : m_items)
        if (!i.inFlight)
            i.dueMs = qMin(i.dueMs, now + effectiveInterval(i));
    if (m_running)
        pump();
}

void PollScheduler::setFillWire(bool on) {
    m_fillWire = on;
    if (m_running)
        pump();
}

PollScheduler::Item *PollScheduler::furthestAlong(qint64 now) {
    Item *best = nullptr;
    Item *bestTip = nullptr;    // while a port is in a joint
    Item *fallingTip = nullptr; // of a port that has just turned busy
    double bestShare = -1, bestTipShare = -1, fallingShare = -1;
    for (Item &i : m_items) {
        if (i.inFlight || !i.parameter || i.pollClass != PollClass::Live || i.dueMs >= kNever ||
            i.parameter->isRefused())
            continue;
        const int iv = effectiveInterval(i);
        const double share = iv > 0 ? double(now - i.polledMs) / iv : 0;
        if (iv > 0 && share > bestShare) {
            best = &i;
            bestShare = share;
        }
        if (iv > 0 && i.role == protocol::Role::TipTemperature && !m_busy.isEmpty() &&
            now - i.sentMs >= kSpareGapMs) {
            if (share > bestTipShare) {
                bestTip = &i;
                bestTipShare = share;
            }
            const auto since = m_busy.constFind({i.device, i.port});
            if (since != m_busy.cend() && now < *since + kFallWatchMs && share > fallingShare) {
                fallingTip = &i;
                fallingShare = share;
            }
        }
    }
    // What the wire has to spare while a joint is under way goes to the tips, up to a reading
    // every kSpareGapMs each: first to a port that has just turned busy, for kFallWatchMs, as the
    // joint's start is traced back along its fall and its lowest point is placed among the
    // readings around it; then to every port's alike, as the return is placed by a fit that the
    // readings' wobble limits, and the next joint on any other port is timed from theirs. Every
    // other value is still read at its own rate. Beyond that (a line faster than any station's,
    // the demo's unpaced one) the spare goes round the live values as when no port is busy.
    return fallingTip ? fallingTip : bestTip ? bestTip : best;
}

namespace {
// Stand, sleep, hibernation and cooling, no tool, a port error: the tip is away from its
// setpoint by design or by a fault, not by a joint.
bool rests(const DeviceModel &device, int port) {
    using protocol::Role;
    const auto numberOf = [&](Role role) {
        const Parameter *p = device.parameter(role, port);
        return p ? p->number() : std::nullopt;
    };
    if (const auto tool = numberOf(Role::ConnectedTool); tool && *tool == 0)
        return true;
    if (const auto error = numberOf(Role::Error); error && *error != 0)
        return true;
    const auto value = numberOf(Role::Status);
    if (!value)
        return false;
    const PortStatus s = PortStatus::fromNumber(*value);
    return s.mode != PortStatus::Mode::Working || s.cooling;
}

// The readings that tell why a port's tip left its band, or why it rests.
bool explainsTip(protocol::Role role) {
    using protocol::Role;
    return role == Role::Status || role == Role::Setpoint || role == Role::ConnectedTool ||
           role == Role::Error;
}
} // namespace

bool PollScheduler::isBusy(DeviceModel *device, int port) const {
    using protocol::Role;
    const Parameter *tip = device->parameter(Role::TipTemperature, port);
    const Parameter *setpoint = device->parameter(Role::Setpoint, port);
    const Parameter *power = device->parameter(Role::Power, port);
    const std::optional<qint64> tipNow = tip ? tip->number() : std::nullopt;
    const qint64 t = tipNow.value_or(0);
    if (rests(*device, port)) {
        const auto low = m_restLow.constFind({device, port});
        return tipNow && low != m_restLow.cend() && t > *low + kWakeRiseK;
    }
    const std::optional<qint64> setNow = setpoint ? setpoint->number() : std::nullopt;
    const qint64 set = setNow.value_or(0);
    // Below: a joint, or the tool put down; above: a new, higher setpoint not read yet.
    if (tipNow && setNow && (t < set - kBusyBelowK || t > set + kBusyBelowK))
        return true;
    const auto powerNow = power ? power->number() : std::nullopt;
    const int full = power && power->spec().max > 0 ? power->spec().max : 1000;
    return powerNow && double(*powerNow) > kBusyPowerShare * full;
}

void PollScheduler::followBusy(DeviceModel *device, int port, protocol::Role read, qint64 now) {
    const QPair<DeviceModel *, int> key{device, port};
    const Parameter *tip = device->parameter(protocol::Role::TipTemperature, port);
    const auto tipNow = tip ? tip->number() : std::nullopt;
    const bool resting = rests(*device, port);
    if (resting && tipNow) {
        // A status, tool or error just read that still says "resting" explains the tip as it is
        // (a tip heating to its sleep temperature is no wake): the climb is measured from here.
        const auto low = m_restLow.find(key);
        if (low == m_restLow.end() || (explainsTip(read) && read != protocol::Role::Setpoint))
            m_restLow.insert(key, *tipNow);
        else
            *low = qMin(*low, *tipNow);
    } else {
        m_restLow.remove(key);
    }
    // One reading that tells why the tip is where it is may come before the tip shows it (an
    // error read on its own interval just after the tool was taken out): the others are read at
    // once too, or a tool taken out and put back between two of its slow readings is never seen.
    if (resting != m_resting.contains(key)) {
        if (resting)
            m_resting.insert(key);
        else
            m_resting.remove(key);
        askWhy(device, port, now);
    }
    const bool was = m_busy.contains(key);
    const bool busy = isBusy(device, port);
    if (busy == was)
        return;
    if (!busy) {
        m_busy.remove(key);
        updateIntervals(m_busy.isEmpty() ? nullptr : device, m_busy.isEmpty() ? -1 : port);
        return;
    }
    const bool first = m_busy.isEmpty();
    m_busy.insert(key, now);
    updateIntervals(first ? nullptr : device, first ? -1 : port);
    for (Item &i : m_items)
        if (i.device == device && i.port == port && !i.inFlight &&
            (i.role == protocol::Role::TipTemperature || i.role == protocol::Role::Power))
            i.dueMs = qMin(i.dueMs, now + effectiveInterval(i));
    askWhy(device, port, now);
}

// A tip leaving its band is a joint, the tool put in its stand, asleep or taken out, a fault, or
// a new setpoint; a resting tip climbing is a wake, a tool put back or a fault cleared. The
// status, the setpoint, the tool and the port's error are read at once, so the event is stamped
// when the tip shows it, a rest is never measured as a joint for want of them, and a heat-up is
// timed from when it began.
void PollScheduler::askWhy(DeviceModel *device, int port, qint64 now) {
    for (Item &i : m_items) {
        if (i.device != device || i.port != port || i.inFlight || !explainsTip(i.role))
            continue;
        i.dueMs = qMin(i.dueMs, now);
        i.first = true; // before the tips that a full wire always has overdue
    }
}

void PollScheduler::start() {
    m_running = true;
    pump();
}

void PollScheduler::stop() {
    m_running = false;
    m_wake.stop();
}

void PollScheduler::pump() {
    if (!m_running)
        return;
    const qint64 now = nowMs();
    if (now < m_holdUntilMs) {
        armWake();
        return;
    }
    while (m_inFlight < m_maxInFlight) {
        // Live first by due time; every second slot (every fourth while a port is in a joint,
        // whose readings come first) the most overdue of the rest first, and every second of
        // those settings, counters and identity before errors and status: a port's many status
        // values, always due on a busy wire, must not starve a page's reads.
        const bool othersTurn = m_busy.isEmpty() ? m_slot % 2 == 1 : m_slot % 4 == 3;
        const bool settingsTurn = othersTurn && m_othersTurns % 2 == 1;
        const auto rank = [settingsTurn](const Item &x) {
            const int r = int(x.pollClass);
            return settingsTurn && x.pollClass == PollClass::Status ? r + int(PollClass::None) : r;
        };
        Item *best = nullptr;
        for (Item &i : m_items) {
            if (i.inFlight || !i.parameter || i.dueMs > now)
                continue;
            if (!best) {
                best = &i;
                continue;
            }
            const bool iLive = i.pollClass == PollClass::Live;
            const bool bestLive = best->pollClass == PollClass::Live;
            if (iLive != bestLive) {
                if (iLive != othersTurn)
                    best = &i;
                continue;
            }
            // Among the rest, errors and status come before settings, counters and identity
            // (on their turn, after them).
            const bool earlier = i.first != best->first ? i.first
                                 : iLive                ? urgency(i, now) < urgency(*best, now)
                                                        : rank(i) < rank(*best) ||
                                               (rank(i) == rank(*best) && i.dueMs < best->dueMs);
            if (earlier)
                best = &i;
        }
        // An early read goes behind every poll waiting in the queue: were it a live poll, a
        // waiting setting (a background poll) would never be sent, as early reads never end.
        const bool early = !best && (m_fillWire || !m_busy.isEmpty());
        if (early)
            best = furthestAlong(now);
        if (!best)
            break;
        ++m_slot;
        if (othersTurn && best->pollClass != PollClass::Live)
            ++m_othersTurns;
        // The order among polls is decided here, fairly, by turns: in the queue every due poll
        // has one priority, or a setting sent on its turn would wait behind live polls that on a
        // full wire never stop coming.
        const Priority prio = early ? Priority::Background : Priority::LivePoll;
        Reply *reply = best->parameter->refresh(prio);
        if (!reply) {
            best->dueMs = kNever;
            continue;
        }
        best->inFlight = true;
        best->first = false;
        best->sentMs = now;
        ++m_inFlight;
        Parameter *param = best->raw;
        connect(reply, &Reply::finished, this, [this, reply, param] {
            --m_inFlight;
            ++m_done;
            const qint64 t = nowMs();
            const bool lineDown =
                reply->error() == ReplyError::NotOpen || reply->error() == ReplyError::Disconnected;
            if (lineDown)
                m_holdUntilMs = t + kLineDownHoldMs;
            for (Item &i : m_items) {
                if (i.raw != param)
                    continue;
                if (m_adaptive && i.port > 0 && !lineDown)
                    followBusy(i.device, i.port, i.role, t);
                i.inFlight = false;
                i.polledMs = t;
                const int iv = effectiveInterval(i);
                i.dueMs = lineDown                                  ? t + qMax(iv, kLineDownHoldMs)
                          : i.parameter && i.parameter->isRefused() ? t + qMax(iv, kRefusedRetryMs)
                          : iv > 0                                  ? t + iv
                                                                    : kNever;
            }
            pump();
        });
    }
    armWake();
}

void PollScheduler::armWake() {
    qint64 next = kNever;
    for (const Item &i : m_items)
        if (!i.inFlight && i.parameter)
            next = qMin(next, i.dueMs);
    next = qMax(next, m_holdUntilMs);
    if (next >= kNever || m_inFlight >= m_maxInFlight)
        return;
    m_wake.start(int(qBound(qint64(0), next - nowMs(), qint64(60000))));
}

} // namespace tipscope::model
