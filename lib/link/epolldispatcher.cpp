#include "epolldispatcher.h"

#include <QCoreApplication>
#include <QSocketNotifier>
#include <QTimerEvent>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <limits>
#include <poll.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <unistd.h>

namespace tipscope::link {

namespace {
// The wait in whole milliseconds that reaches `us`: rounded up, so that a timer is never early.
int toWaitMs(qint64 us) {
    return int(qBound(qint64(0), (us + 999) / 1000, qint64(std::numeric_limits<int>::max())));
}
} // namespace

EpollDispatcher::EpollDispatcher(QObject *parent)
    : QAbstractEventDispatcher(parent)
    , m_epoll(::epoll_create1(EPOLL_CLOEXEC))
    , m_wake(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
    if (!isValid())
        return;
    epoll_event wake{};
    wake.events = EPOLLIN;
    wake.data.fd = m_wake;
    if (::epoll_ctl(m_epoll, EPOLL_CTL_ADD, m_wake, &wake) != 0) {
        ::close(m_wake);
        m_wake = -1;
    }
}

EpollDispatcher::~EpollDispatcher() {
    if (m_wake >= 0)
        ::close(m_wake);
    if (m_epoll >= 0)
        ::close(m_epoll);
}

qint64 EpollDispatcher::nowUs() {
    using namespace std::chrono;
    return duration_cast<microseconds>(steady_clock::now().time_since_epoch()).count();
}

bool EpollDispatcher::processEvents(QEventLoop::ProcessEventsFlags flags) {
    m_interrupted = false;
    Q_EMIT awake();
    QCoreApplication::sendPostedEvents();
    if (m_interrupted)
        return false;
    const bool timers = !(flags & QEventLoop::X11ExcludeTimers);
    const bool sockets = !(flags & QEventLoop::ExcludeSocketNotifiers);
    int waitMs = 0;
    // A descriptor epoll cannot watch (a regular file) is always ready, as poll() says of it.
    if ((flags & QEventLoop::WaitForMoreEvents) && !(sockets && alwaysReadyToActivate()))
        waitMs = timers ? timeToNextTimer(nowUs()) : -1;
    if (waitMs != 0)
        Q_EMIT aboutToBlock();
    int ready = 0;
    // A wake-up drained counts as an event, as in Qt's loops: processEvents(flags, maxtime)
    // goes on while there is something, and a queued call that posts the next is something.
    bool any = false;
    if (sockets) {
        ready = ::epoll_wait(m_epoll, m_events.data(), int(m_events.size()), waitMs);
        if (ready < 0 && errno != EINTR) // a signal ends the wait early, and nothing is lost
            qWarning("EpollDispatcher: epoll_wait failed: %s", strerror(errno));
    } else {
        // Only a wake-up or a timer may end the wait: the notifiers stay out of it.
        pollfd wake{m_wake, POLLIN, 0};
        if (::poll(&wake, 1, waitMs) == 1)
            any = drainWake();
    }
    if (waitMs != 0)
        Q_EMIT awake();
    if (sockets)
        any = activateNotifiers(qMax(0, ready)) || any;
    if (timers)
        any = activateTimers() || any;
    return any;
}

bool EpollDispatcher::alwaysReadyToActivate() const {
    for (int fd : m_alwaysReady) {
        const Watch &w = m_watches[fd];
        if (w.read || w.write)
            return true;
    }
    return false;
}

bool EpollDispatcher::activateNotifiers(int ready) {
    std::vector<QSocketNotifier *> list;
    bool woken = false;
    for (int i = 0; i < ready; ++i) {
        const int fd = m_events[size_t(i)].data.fd;
        if (fd == m_wake) {
            woken = drainWake();
            continue;
        }
        const auto w = m_watches.constFind(fd);
        if (w == m_watches.cend()) {
            // In the set but watched by nobody (closed and reopened behind its notifiers'
            // back): out of the set, or it would end every wait.
            (void)::epoll_ctl(m_epoll, EPOLL_CTL_DEL, fd, nullptr);
            continue;
        }
        const quint32 e = m_events[size_t(i)].events;
        // A hang-up or an error is news to whoever reads or writes, as poll() has it.
        if (w->read && (e & (EPOLLIN | EPOLLHUP | EPOLLERR)))
            list.push_back(w->read);
        if (w->write && (e & (EPOLLOUT | EPOLLHUP | EPOLLERR)))
            list.push_back(w->write);
        if (w->exception && (e & (EPOLLPRI | EPOLLHUP | EPOLLERR)))
            list.push_back(w->exception);
    }
    for (int fd : std::as_const(m_alwaysReady)) {
        const Watch &w = m_watches[fd];
        for (QSocketNotifier *n : {w.read, w.write})
            if (n)
                list.push_back(n);
    }
    // A notifier activated may unregister one still waiting in this list (unregister sets it
    // to null) or run a loop of its own, with a list of its own: a notifier is taken out of
    // every list as it is activated, so a readiness seen by two loops is delivered once (a
    // handler reading a blocking descriptor would otherwise wait for bytes that never come).
    m_readyLists.push_back(&list);
    bool any = woken;
    for (size_t i = 0; i < list.size(); ++i) {
        QSocketNotifier *n = list[i];
        if (!n)
            continue;
        forgetReady(n);
        QEvent activation(QEvent::SockAct);
        QCoreApplication::sendEvent(n, &activation);
        any = true;
    }
    m_readyLists.pop_back();
    return any;
}

// Read first, then let the next wakeUp() write: the other way round, a wakeUp() between the two
// would be read here with the flag still saying pending, and no wakeUp() would write again.
bool EpollDispatcher::drainWake() {
    quint64 count = 0;
    const bool read = ::read(m_wake, &count, sizeof count) == ssize_t(sizeof count);
    m_wakePending = false;
    return read;
}

void EpollDispatcher::forgetReady(QSocketNotifier *notifier) {
    for (std::vector<QSocketNotifier *> *list : m_readyLists)
        std::replace(list->begin(), list->end(), notifier, static_cast<QSocketNotifier *>(nullptr));
}

void EpollDispatcher::registerSocketNotifier(QSocketNotifier *notifier) {
    const int fd = int(notifier->socket());
    Watch &w = m_watches[fd];
    QSocketNotifier **slot = notifier->type() == QSocketNotifier::Read    ? &w.read
                             : notifier->type() == QSocketNotifier::Write ? &w.write
                                                                          : &w.exception;
    if (*slot && *slot != notifier)
        qWarning("EpollDispatcher: a second notifier of one kind for socket %d", fd);
    *slot = notifier;
    // Told again even where the set seems to hold it: the descriptor may be a new one under
    // an old number, which the set dropped when the old one closed.
    updateWatch(fd, true);
}

void EpollDispatcher::unregisterSocketNotifier(QSocketNotifier *notifier) {
    forgetReady(notifier);
    const int fd = int(notifier->socket());
    const auto w = m_watches.find(fd);
    if (w == m_watches.end())
        return;
    for (QSocketNotifier **slot : {&w->read, &w->write, &w->exception})
        if (*slot == notifier)
            *slot = nullptr;
    updateWatch(fd);
}

void EpollDispatcher::updateWatch(int fd, bool force) {
    const auto w = m_watches.find(fd);
    if (w == m_watches.end())
        return;
    const quint32 want = (w->read ? quint32(EPOLLIN) : 0) | (w->write ? quint32(EPOLLOUT) : 0) |
                         (w->exception ? quint32(EPOLLPRI) : 0);
    if (want == w->events && !(force && want != 0 && !m_alwaysReady.contains(fd)))
        return;
    if (want == 0) {
        if (!m_alwaysReady.remove(fd))
            (void)::epoll_ctl(m_epoll, EPOLL_CTL_DEL, fd, nullptr);
        m_watches.erase(w);
        return;
    }
    epoll_event e{};
    e.events = want;
    e.data.fd = fd;
    int rc = ::epoll_ctl(m_epoll, w->events ? EPOLL_CTL_MOD : EPOLL_CTL_ADD, fd, &e);
    // A descriptor closed and its number given again, with its notifiers not yet told: the set
    // dropped the old one (ENOENT), or still holds it (EEXIST).
    if (rc != 0 && errno == ENOENT)
        rc = ::epoll_ctl(m_epoll, EPOLL_CTL_ADD, fd, &e);
    else if (rc != 0 && errno == EEXIST)
        rc = ::epoll_ctl(m_epoll, EPOLL_CTL_MOD, fd, &e);
    if (rc != 0 && errno == EPERM)
        m_alwaysReady.insert(fd);
    else if (rc != 0)
        qWarning("EpollDispatcher: socket %d cannot be watched: %s", fd, strerror(errno));
    w->events = want;
}

void EpollDispatcher::registerTimer(int timerId, qint64 interval, Qt::TimerType timerType,
                                    QObject *object) {
    qint64 ms = qMax<qint64>(0, interval);
    if (timerType == Qt::VeryCoarseTimer) // whole seconds, as Qt keeps them
        ms = (ms + 500) / 1000 * 1000;
    m_timers.push_back({timerId, ms, timerType, object, nowUs() + ms * 1000, false});
}

bool EpollDispatcher::unregisterTimer(int timerId) {
    const auto t = std::find_if(m_timers.begin(), m_timers.end(),
                                [timerId](const Timer &x) { return x.id == timerId; });
    if (t == m_timers.end())
        return false;
    m_timers.erase(t);
    return true;
}

bool EpollDispatcher::unregisterTimers(QObject *object) {
    const auto end = std::remove_if(m_timers.begin(), m_timers.end(),
                                    [object](const Timer &x) { return x.object == object; });
    const bool any = end != m_timers.end();
    m_timers.erase(end, m_timers.end());
    return any;
}

QList<QAbstractEventDispatcher::TimerInfo>
EpollDispatcher::registeredTimers(QObject *object) const {
    QList<TimerInfo> list;
    for (const Timer &t : m_timers)
        if (t.object == object)
            list.append(TimerInfo(t.id, int(t.intervalMs), t.type));
    return list;
}

int EpollDispatcher::remainingTime(int timerId) {
    for (const Timer &t : m_timers)
        if (t.id == timerId)
            return toWaitMs(t.dueUs - nowUs());
    return -1;
}

int EpollDispatcher::timeToNextTimer(qint64 now) const {
    qint64 next = -1;
    for (const Timer &t : m_timers)
        if (!t.active && (next < 0 || t.dueUs < next))
            next = t.dueUs;
    return next < 0 ? -1 : toWaitMs(next - now);
}

bool EpollDispatcher::activateTimers() {
    const qint64 now = nowUs();
    std::vector<std::pair<qint64, int>> due; // (when, id), earliest first
    for (const Timer &t : m_timers)
        if (!t.active && t.dueUs <= now)
            due.emplace_back(t.dueUs, t.id);
    std::sort(due.begin(), due.end());
    const auto find = [this](int id) {
        return std::find_if(m_timers.begin(), m_timers.end(),
                            [id](const Timer &x) { return x.id == id; });
    };
    for (const auto &[when, id] : due) {
        // Looked up again each time: an earlier timer's event may have stopped or added timers.
        auto t = find(id);
        // Gone, firing in an outer turn, fired already by a loop a handler ran, or restarted
        // under the same id (Qt gives a freed id out again first): not due now.
        if (t == m_timers.end() || t->active || t->dueUs > now)
            continue;
        // A timer that fell behind (a long handler, a suspended machine) fires once and keeps
        // its rhythm from now, as Qt's do.
        const qint64 intervalUs = t->intervalMs * 1000;
        t->dueUs = t->dueUs + intervalUs > now ? t->dueUs + intervalUs : now + intervalUs;
        t->active = true;
        QObject *object = t->object;
        QTimerEvent event(id);
        QCoreApplication::sendEvent(object, &event);
        if (auto after = find(id); after != m_timers.end())
            after->active = false;
    }
    return !due.empty();
}

void EpollDispatcher::wakeUp() {
    if (m_wakePending.exchange(true))
        return;
    const quint64 one = 1;
    (void)!::write(m_wake, &one, sizeof one);
}

void EpollDispatcher::interrupt() {
    m_interrupted = true;
    wakeUp();
}

bool useEpollUnlessTold() {
    if (qEnvironmentVariable("TIPSCOPE_EVENT_LOOP") == QLatin1String("qt"))
        return false;
    auto *dispatcher = new EpollDispatcher;
    if (!dispatcher->isValid()) {
        delete dispatcher;
        return false;
    }
    QCoreApplication::setEventDispatcher(dispatcher);
    return true;
}

} // namespace tipscope::link
