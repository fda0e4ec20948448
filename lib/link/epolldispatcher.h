// EpollDispatcher: an event loop for a thread that watches many lines, on Linux's epoll.
//
// Qt's event dispatchers (glib's and its own) hand poll() every watched descriptor on each turn of
// the loop, and the kernel looks at each of them: on a line service with 32 lines whose answers
// come a byte or two at a time, that look was the largest single cost of tipscope-agent
// (docs/performance.md). epoll keeps the set in the kernel and reports only the descriptors that
// are ready, so a turn costs what is ready, not what is watched; the price is a system call each
// time a notifier is switched on or off (a socket's write notifier around each request).
//
// It does what the loop of a QCoreApplication needs: socket notifiers (read, write, exception),
// timers (every kind kept to the millisecond: coarseness is a permission, not a duty), posted
// events and deferred deletes (QCoreApplication::sendPostedEvents), wakeUp() from any thread
// (an eventfd), interrupt(), aboutToBlock() and awake(). It knows nothing of a window system: a
// QGuiApplication keeps Qt's own. Install it before the application exists
// (QCoreApplication::setEventDispatcher); useEpollUnlessTold() does that unless
// TIPSCOPE_EVENT_LOOP=qt asks for Qt's.
#pragma once

#include <QAbstractEventDispatcher>
#include <QHash>
#include <QList>
#include <QSet>
#include <QtGlobal>
#include <array>
#include <atomic>
#include <sys/epoll.h>
#include <vector>

class QSocketNotifier;

namespace tipscope::link {

class EpollDispatcher : public QAbstractEventDispatcher {
    Q_OBJECT
public:
    explicit EpollDispatcher(QObject *parent = nullptr);
    ~EpollDispatcher() override;

    // False when the kernel gave no epoll set or eventfd (then the dispatcher must not be used).
    [[nodiscard]] bool isValid() const { return m_epoll >= 0 && m_wake >= 0; }

    bool processEvents(QEventLoop::ProcessEventsFlags flags) override;

    void registerSocketNotifier(QSocketNotifier *notifier) override;
    void unregisterSocketNotifier(QSocketNotifier *notifier) override;

    void registerTimer(int timerId, qint64 interval, Qt::TimerType timerType,
                       QObject *object) override;
    bool unregisterTimer(int timerId) override;
    bool unregisterTimers(QObject *object) override;
    [[nodiscard]] QList<TimerInfo> registeredTimers(QObject *object) const override;
    int remainingTime(int timerId) override;

    void wakeUp() override;
    void interrupt() override;

private:
    struct Watch {
        QSocketNotifier *read = nullptr;
        QSocketNotifier *write = nullptr;
        QSocketNotifier *exception = nullptr;
        quint32 events = 0; // what the epoll set holds for the descriptor
    };
    struct Timer {
        int id = 0;
        qint64 intervalMs = 0;
        Qt::TimerType type = Qt::CoarseTimer;
        QObject *object = nullptr;
        qint64 dueUs = 0;    // kept in microseconds: a timer never fires before its time
        bool active = false; // its event is being delivered: it does not fire again inside
    };

    void updateWatch(int fd, bool force = false);
    [[nodiscard]] bool alwaysReadyToActivate() const;
    void forgetReady(QSocketNotifier *notifier);
    [[nodiscard]] static qint64 nowUs();
    // The wait until the next timer is due, in ms; -1 when none is registered.
    [[nodiscard]] int timeToNextTimer(qint64 nowUs) const;
    bool activateTimers();
    bool activateNotifiers(int ready);
    bool drainWake();

    static constexpr int kMaxReadyPerTurn = 256;

    int m_epoll = -1;
    int m_wake = -1;
    std::atomic<bool> m_wakePending{false};
    std::atomic<bool> m_interrupted{false};
    QHash<int, Watch> m_watches;
    QSet<int> m_alwaysReady; // descriptors epoll refuses (regular files): ready every turn
    std::vector<Timer> m_timers;
    std::array<epoll_event, kMaxReadyPerTurn> m_events{};
    // The notifiers ready in each turn under way (a handler may run a loop of its own), in the
    // order epoll gave them; one unregistered meanwhile is set to null, never activated after.
    std::vector<std::vector<QSocketNotifier *> *> m_readyLists;
};

// Installs an EpollDispatcher for the main thread unless the environment says
// TIPSCOPE_EVENT_LOOP=qt. Call before the QCoreApplication is made; returns whether it did.
bool useEpollUnlessTold();

} // namespace tipscope::link
