// sendNow() against a real loopback connection: on a connected socket with nothing waiting in
// Qt's buffer the system takes the bytes at once; with bytes waiting in the buffer it takes none,
// so what the caller writes next through Qt keeps its place behind them; an unconnected socket
// takes none. The peer reads everything in the order it was sent.
#include "link/socketsend.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

namespace tst_socketsend {

using tipscope::link::sendNow;

namespace {

constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on

// A connected pair on loopback: `client` is ours, `peer` the other end.
struct Pair {
    Pair() {
        if (!server.listen(QHostAddress::LocalHost))
            return;
        client.connectToHost(QHostAddress::LocalHost, server.serverPort());
        if (client.waitForConnected(kWaitMs) && server.waitForNewConnection(kWaitMs))
            peer = server.nextPendingConnection();
    }
    // What the peer has read once `size` bytes came, or all it got within the wait.
    QByteArray receive(qsizetype size) {
        QByteArray got;
        (void)QTest::qWaitFor(
            [&] {
                got += peer->readAll();
                return got.size() >= size;
            },
            kWaitMs);
        return got;
    }
    QTcpServer server;
    QTcpSocket client;
    QTcpSocket *peer = nullptr;
};

} // namespace

class TestSocketSend : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aConnectedSocketWithNothingWaitingSendsAtOnce();
    void bytesWaitingInQtsBufferGoFirst();
    void anUnconnectedSocketTakesNothing();
};

void TestSocketSend::aConnectedSocketWithNothingWaitingSendsAtOnce() {
    Pair p;
    QVERIFY(p.peer);
    const QByteArray frame("\x02"
                           "0001RSMN\x03\x0b");
    QCOMPARE(sendNow(p.client, frame), frame.size());
    QCOMPARE(p.client.bytesToWrite(), qint64(0)); // Qt never held them
    QCOMPARE(p.receive(frame.size()), frame);
}

void TestSocketSend::bytesWaitingInQtsBufferGoFirst() {
    Pair p;
    QVERIFY(p.peer);
    QCOMPARE(p.client.write("first "), qint64(6)); // held by Qt until the event loop runs
    QVERIFY(p.client.bytesToWrite() > 0);
    QCOMPARE(sendNow(p.client, "second"), qsizetype(0));
    QCOMPARE(p.client.write("second"), qint64(6)); // the caller's fallback, behind them
    QCOMPARE(p.receive(12), QByteArray("first second"));
}

void TestSocketSend::anUnconnectedSocketTakesNothing() {
    QTcpSocket never;
    QCOMPARE(sendNow(never, "bytes"), qsizetype(0));
    Pair p;
    QVERIFY(p.peer);
    p.client.disconnectFromHost();
    QCOMPARE(sendNow(p.client, "bytes"), qsizetype(0));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSocketSend)

} // namespace tst_socketsend

#include "tst_socketsend.moc"
