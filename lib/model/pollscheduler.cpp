#include "pollscheduler.h"

#include "devicemodel.h"

#include <limits>

namespace tipscope::model {

using namespace tipscope::link;

namespace {
constexpr qint64 kNever = std::numeric_limits<qint64>::max() / 2;
constexpr int kLineDownHoldMs = 1000;
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
        m_items.push_back(
            {p, device, c, p->meta().usesPort() ? p->spec().port : 0, nowMs(), false});
    }
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
}

void PollScheduler::setInterval(PollClass c, int ms) {
    if (c == PollClass::None)
        return;
    m_intervals[int(c)] = qMax(0, ms);
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

int PollScheduler::effectiveInterval(const Item &i) const {
    if (i.pollClass == PollClass::Live && i.port > 0 && !m_visible.value(i.device).contains(i.port))
        return m_intervals[int(PollClass::Status)];
    return m_intervals[int(i.pollClass)];
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
        // Live first by due time; every fourth slot, the most overdue of the rest first.
        const bool othersTurn = m_slot % 4 == 3;
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
            // Among the rest, errors and status come before settings, counters and identity.
            const bool earlier =
                iLive ? i.dueMs < best->dueMs
                      : i.pollClass < best->pollClass ||
                            (i.pollClass == best->pollClass && i.dueMs < best->dueMs);
            if (earlier)
                best = &i;
        }
        if (!best)
            break;
        ++m_slot;
        const PollClass c = best->pollClass;
        const Priority prio = c == PollClass::Live || c == PollClass::Status ? Priority::LivePoll
                                                                             : Priority::Background;
        Reply *reply = best->parameter->refresh(prio);
        if (!reply) {
            best->dueMs = kNever;
            continue;
        }
        best->inFlight = true;
        ++m_inFlight;
        QPointer<Parameter> param = best->parameter;
        connect(reply, &Reply::finished, this, [this, reply, param] {
            --m_inFlight;
            ++m_done;
            const qint64 t = nowMs();
            const bool lineDown =
                reply->error() == ReplyError::NotOpen || reply->error() == ReplyError::Disconnected;
            if (lineDown)
                m_holdUntilMs = t + kLineDownHoldMs;
            for (Item &i : m_items) {
                if (i.parameter != param)
                    continue;
                i.inFlight = false;
                const int iv = effectiveInterval(i);
                i.dueMs = lineDown ? t + qMax(iv, kLineDownHoldMs) : iv > 0 ? t + iv : kNever;
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
