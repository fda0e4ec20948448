// EpollDispatcher as the main thread's event loop, installed as tipscope-agent installs it:
// timers in order and at every turn when their interval is 0, socket notifiers that come when
// their socket is ready and not when they are off, a notifier deleted by another in the same
// turn never activated, a descriptor epoll cannot watch still served, posted calls and deferred
// deletes carried out, a wait ended from another thread, nested loops, and Qt's own network
// classes (a QTcpServer and a QTcpSocket) talking across it.
#include "link/epolldispatcher.h"
#include "testmain.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QPointer>
#include <QSocketNotifier>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryFile>
#include <QTest>
#include <QTimer>
#include <atomic>
#include <cstring>
#include <fcntl.h>
#include <functional>
#include <memory>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

namespace tst_epolldispatcher {

using tipscope::link::EpollDispatcher;

// A connected pair of local sockets, closed at the end.
struct SocketPair {
    int fd[2] = {-1, -1};
    SocketPair() { (void)::socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0, fd); }
    ~SocketPair() {
        for (int f : fd)
            if (f >= 0)
                ::close(f);
    }
    void send(const char *bytes) const { (void)!::write(fd[1], bytes, strlen(bytes)); }
    [[nodiscard]] QByteArray take() const {
        char buf[256];
        const ssize_t n = ::read(fd[0], buf, sizeof buf);
        return n > 0 ? QByteArray(buf, int(n)) : QByteArray();
    }
};

// Runs a loop until `done` or 5 s, whichever first; the loop's own event loop, not a test's qWait.
bool spinUntil(const std::function<bool()> &done) {
    QElapsedTimer waited;
    waited.start();
    while (!done() && waited.elapsed() < 5000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    return done();
}

// Runs the loop for `ms`.
void runFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, Qt::PreciseTimer, &loop, &QEventLoop::quit);
    loop.exec();
}

class TstEpollDispatcher : public QObject {
    Q_OBJECT
public:
    static void initMain() { (void)tipscope::link::useEpollUnlessTold(); }

private Q_SLOTS:
    void initTestCase();
    void timersFireInTheOrderTheyAreDue();
    void aTimerWithoutIntervalFiresAtEveryTurn();
    void aStoppedTimerNeverFires();
    void aReadNotifierComesWhenBytesWaitAndNotWhenOff();
    void aWriteNotifierComesWhenTheSocketTakesBytes();
    void aNotifierDeletedInTheSameTurnIsNeverActivated();
    void aFileEpollCannotWatchIsStillServed();
    void postedCallsAndDeferredDeletesAreCarriedOut();
    void anotherThreadEndsTheWait();
    void aLoopInsideAHandlerGoesOn();
    void aTimerFiredByALoopInsideAHandlerIsNotFiredAgain();
    void aTimerRestartedByAnotherIsNotFiredAtOnce();
    void aNotifierActivatedByALoopInsideAHandlerIsNotActivatedAgain();
    void aFloodOfCallsFromAnotherThreadIsDeliveredWhole();
    void aChainOfQueuedCallsRunsWithinOneBoundedProcessEvents();
    void qtNetworkClassesTalkAcrossIt();
};

void TstEpollDispatcher::initTestCase() {
    QVERIFY2(qobject_cast<EpollDispatcher *>(QAbstractEventDispatcher::instance()),
             "the main thread's loop is not the epoll one (TIPSCOPE_EVENT_LOOP=qt set?)");
}

void TstEpollDispatcher::timersFireInTheOrderTheyAreDue() {
    QStringList fired;
    QTimer::singleShot(60, Qt::PreciseTimer, this, [&] { fired << QStringLiteral("60"); });
    QTimer::singleShot(20, Qt::CoarseTimer, this, [&] { fired << QStringLiteral("20"); });
    QTimer::singleShot(40, Qt::PreciseTimer, this, [&] { fired << QStringLiteral("40"); });
    QElapsedTimer since;
    since.start();
    QVERIFY(spinUntil([&] { return fired.size() == 3; }));
    QCOMPARE(fired,
             (QStringList{QStringLiteral("20"), QStringLiteral("40"), QStringLiteral("60")}));
    QVERIFY(since.elapsed() >= 60);
}

void TstEpollDispatcher::aTimerWithoutIntervalFiresAtEveryTurn() {
    QTimer zero;
    zero.setInterval(0);
    int fired = 0;
    connect(&zero, &QTimer::timeout, this, [&] { ++fired; });
    zero.start();
    for (int i = 0; i < 10; ++i)
        QCoreApplication::processEvents();
    QCOMPARE(fired, 10);
}

void TstEpollDispatcher::aStoppedTimerNeverFires() {
    QTimer timer;
    timer.setInterval(10);
    int fired = 0;
    connect(&timer, &QTimer::timeout, this, [&] { ++fired; });
    timer.start();
    QVERIFY(spinUntil([&] { return fired >= 2; }));
    timer.stop();
    const int atStop = fired;
    runFor(100);
    QCOMPARE(fired, atStop);
}

void TstEpollDispatcher::aReadNotifierComesWhenBytesWaitAndNotWhenOff() {
    SocketPair pair;
    QSocketNotifier notifier(pair.fd[0], QSocketNotifier::Read);
    QByteArray got;
    connect(&notifier, &QSocketNotifier::activated, this, [&] { got += pair.take(); });
    pair.send("hello");
    QVERIFY(spinUntil([&] { return got == "hello"; }));

    notifier.setEnabled(false);
    pair.send("later");
    runFor(100);
    QCOMPARE(got, QByteArray("hello"));
    notifier.setEnabled(true);
    QVERIFY(spinUntil([&] { return got == "hellolater"; }));
}

void TstEpollDispatcher::aWriteNotifierComesWhenTheSocketTakesBytes() {
    SocketPair pair;
    QSocketNotifier readable(pair.fd[1], QSocketNotifier::Read); // the same descriptor, both kinds
    QSocketNotifier writable(pair.fd[1], QSocketNotifier::Write);
    int writes = 0;
    connect(&writable, &QSocketNotifier::activated, this, [&] {
        ++writes;
        writable.setEnabled(false);
    });
    QVERIFY(spinUntil([&] { return writes == 1; }));
    int reads = 0;
    connect(&readable, &QSocketNotifier::activated, this, [&] {
        char c;
        reads += int(::read(pair.fd[1], &c, 1));
    });
    (void)!::write(pair.fd[0], "x", 1);
    QVERIFY(spinUntil([&] { return reads == 1; }));
    QCOMPARE(writes, 1);
}

void TstEpollDispatcher::aNotifierDeletedInTheSameTurnIsNeverActivated() {
    SocketPair a, b;
    auto first = std::make_unique<QSocketNotifier>(a.fd[0], QSocketNotifier::Read);
    auto second = std::make_unique<QSocketNotifier>(b.fd[0], QSocketNotifier::Read);
    int activations = 0;
    // Whichever comes first ends the other: exactly one is activated, and nothing touches the
    // deleted one.
    connect(first.get(), &QSocketNotifier::activated, this, [&] {
        ++activations;
        (void)a.take();
        second.reset();
    });
    connect(second.get(), &QSocketNotifier::activated, this, [&] {
        ++activations;
        (void)b.take();
        first.reset();
    });
    a.send("1");
    b.send("2");
    QVERIFY(spinUntil([&] { return activations > 0; }));
    for (int i = 0; i < 5; ++i)
        QCoreApplication::processEvents();
    QCOMPARE(activations, 1);
    QVERIFY(!first || !second);
}

void TstEpollDispatcher::aFileEpollCannotWatchIsStillServed() {
    QTemporaryFile file;
    QVERIFY(file.open());
    file.write("data");
    file.flush();
    const int fd = ::open(QFile::encodeName(file.fileName()).constData(), O_RDONLY);
    QVERIFY(fd >= 0);
    int activations = 0;
    {
        QSocketNotifier notifier(fd, QSocketNotifier::Read);
        connect(&notifier, &QSocketNotifier::activated, this, [&] { ++activations; });
        QVERIFY(spinUntil([&] { return activations >= 2; })); // ready at every turn, as in poll()
    }
    ::close(fd);
}

void TstEpollDispatcher::postedCallsAndDeferredDeletesAreCarriedOut() {
    bool called = false;
    QMetaObject::invokeMethod(
        this, [&] { called = true; }, Qt::QueuedConnection);
    QPointer<QObject> doomed = new QObject;
    doomed->deleteLater();
    QEventLoop loop;
    QTimer::singleShot(50, &loop, &QEventLoop::quit);
    loop.exec();
    QVERIFY(called);
    QVERIFY(doomed.isNull());
}

void TstEpollDispatcher::anotherThreadEndsTheWait() {
    QEventLoop loop;
    bool failedByTimer = false;
    QTimer::singleShot(10000, &loop, [&] {
        failedByTimer = true;
        loop.quit();
    });
    std::thread other([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        QMetaObject::invokeMethod(&loop, &QEventLoop::quit, Qt::QueuedConnection);
    });
    loop.exec();
    other.join();
    QVERIFY(!failedByTimer);
}

void TstEpollDispatcher::aLoopInsideAHandlerGoesOn() {
    SocketPair pair;
    QSocketNotifier notifier(pair.fd[0], QSocketNotifier::Read);
    int outer = 0, innerTimers = 0;
    connect(&notifier, &QSocketNotifier::activated, this, [&] {
        ++outer;
        (void)pair.take();
        // A modal wait inside a handler: timers and posted calls go on in it.
        QEventLoop inner;
        QTimer tick;
        connect(&tick, &QTimer::timeout, &inner, [&] {
            if (++innerTimers == 3)
                inner.quit();
        });
        tick.start(5);
        inner.exec();
    });
    pair.send("x");
    QVERIFY(spinUntil([&] { return outer == 1 && innerTimers == 3; }));
    QCOMPARE(outer, 1);
}

void TstEpollDispatcher::aTimerFiredByALoopInsideAHandlerIsNotFiredAgain() {
    // Both due in the same turn; the first runs the loop in its handler, which fires the second.
    QTimer first, second;
    first.setSingleShot(true);
    int seconds = 0;
    connect(&second, &QTimer::timeout, this, [&] { ++seconds; });
    connect(&first, &QTimer::timeout, this, [&] {
        QElapsedTimer inner;
        inner.start();
        while (seconds == 0 && inner.elapsed() < 2000)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    });
    first.start(300);
    second.start(300); // again 300 ms after it fired: not within the run below
    runFor(450);
    QCOMPARE(seconds, 1); // once in the inner loop, not again in the outer turn
}

void TstEpollDispatcher::aTimerRestartedByAnotherIsNotFiredAtOnce() {
    QTimer first, second;
    first.setSingleShot(true);
    second.setSingleShot(true);
    QElapsedTimer sinceRestart;
    qint64 firedAfter = -1;
    connect(&second, &QTimer::timeout, this, [&] { firedAfter = sinceRestart.elapsed(); });
    connect(&first, &QTimer::timeout, this, [&] {
        second.start(300); // kills its id and takes one: Qt hands the freed id out first
        sinceRestart.start();
    });
    first.start(20);
    second.start(20);
    QVERIFY(spinUntil([&] { return firedAfter >= 0; }));
    QVERIFY2(firedAfter >= 300, qPrintable(QString::number(firedAfter)));
}

void TstEpollDispatcher::aNotifierActivatedByALoopInsideAHandlerIsNotActivatedAgain() {
    SocketPair a, b;
    QSocketNotifier first(a.fd[0], QSocketNotifier::Read);
    QSocketNotifier second(b.fd[0], QSocketNotifier::Read);
    int firsts = 0, seconds = 0;
    connect(&second, &QSocketNotifier::activated, this, [&] {
        ++seconds;
        (void)b.take();
    });
    connect(&first, &QSocketNotifier::activated, this, [&] {
        ++firsts;
        (void)a.take();
        QElapsedTimer inner;
        inner.start();
        while (seconds == 0 && inner.elapsed() < 2000)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    });
    // Both ready before the loop looks: whichever comes first, the other is seen by both loops.
    a.send("1");
    b.send("2");
    QVERIFY(spinUntil([&] { return firsts == 1 && seconds == 1; }));
    runFor(50);
    QCOMPARE(firsts, 1);
    QCOMPARE(seconds, 1);
}

void TstEpollDispatcher::aFloodOfCallsFromAnotherThreadIsDeliveredWhole() {
    // Each call may fall between the loop reading its wake-up and allowing the next: none may
    // be left waiting for a wake-up that never comes.
    constexpr int kCalls = 200000;
    int delivered = 0;
    std::atomic<bool> stop{false};
    std::thread other([&] {
        for (int i = 0; i < kCalls && !stop; ++i) {
            QMetaObject::invokeMethod(
                this, [&] { ++delivered; }, Qt::QueuedConnection);
            if (i % 64 == 0)
                std::this_thread::yield();
        }
    });
    QEventLoop loop;
    QTimer check;
    connect(&check, &QTimer::timeout, &loop, [&] {
        if (delivered == kCalls)
            loop.quit();
    });
    check.start(20);
    QTimer::singleShot(30000, &loop, &QEventLoop::quit);
    loop.exec();
    stop = true;
    other.join();
    QCOMPARE(delivered, kCalls);
    // And a wake-up still ends a wait with no timer due.
    check.stop();
    bool quitByCall = false;
    std::thread last([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        QMetaObject::invokeMethod(
            &loop,
            [&] {
                quitByCall = true;
                loop.quit();
            },
            Qt::QueuedConnection);
    });
    QTimer::singleShot(5000, &loop, &QEventLoop::quit);
    loop.exec();
    last.join();
    QVERIFY(quitByCall);
}

void TstEpollDispatcher::aChainOfQueuedCallsRunsWithinOneBoundedProcessEvents() {
    int links = 0;
    std::function<void()> next = [&] {
        if (++links < 10)
            QMetaObject::invokeMethod(this, next, Qt::QueuedConnection);
    };
    QMetaObject::invokeMethod(this, next, Qt::QueuedConnection);
    QCoreApplication::processEvents(QEventLoop::AllEvents, 2000);
    QCOMPARE(links, 10);
}

void TstEpollDispatcher::qtNetworkClassesTalkAcrossIt() {
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost));
    QTcpSocket client;
    client.connectToHost(QHostAddress::LocalHost, server.serverPort());
    QVERIFY(spinUntil([&] { return server.hasPendingConnections(); }));
    std::unique_ptr<QTcpSocket> accepted(server.nextPendingConnection());
    connect(accepted.get(), &QTcpSocket::readyRead, this,
            [&] { accepted->write(accepted->readAll().toUpper()); });
    QVERIFY(spinUntil([&] { return client.state() == QAbstractSocket::ConnectedState; }));
    QByteArray echoed;
    connect(&client, &QTcpSocket::readyRead, this, [&] { echoed += client.readAll(); });
    for (int i = 0; i < 100; ++i) {
        client.write("ping ");
        QVERIFY(spinUntil([&] { return echoed.size() == (i + 1) * 5; }));
    }
    QCOMPARE(echoed.left(10), QByteArray("PING PING "));
    accepted->disconnectFromHost();
    QVERIFY(spinUntil([&] { return client.state() == QAbstractSocket::UnconnectedState; }));
}

TIPSCOPE_TEST_GUILESS_MAIN(TstEpollDispatcher)

} // namespace tst_epolldispatcher

#include "tst_epolldispatcher.moc"
