// TcpTransport against a real QTcpServer on the loopback: it opens, sends exactly what it is
// given and says so, hands on what arrives however the network splits it, reports a peer that
// closes as a dropped line with the reason, and an open that cannot succeed as a failure that
// says why, never as a drop; a connection that is never made gives up after the connect timeout.
#include "fullbacklog.h"
#include "link/tcptransport.h"
#include "protocol/frame.h"
#include "protocol/framedecoder.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <memory>

namespace tst_tcptransport {

using namespace tipscope::link;
using tipscope::protocol::Frame;

namespace {

constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on

// A loopback server that keeps the one connection it accepts.
struct Server {
    Server() { QVERIFY(server.listen(QHostAddress::LocalHost)); }

    // Waits for the transport's connection; null when none came.
    QTcpSocket *accept() {
        if (!peer && (server.hasPendingConnections() || server.waitForNewConnection(kWaitMs)))
            peer = server.nextPendingConnection();
        return peer;
    }
    [[nodiscard]] quint16 port() const { return server.serverPort(); }

    QTcpServer server;
    QTcpSocket *peer = nullptr; // owned by the server
};

// A port on the loopback where nothing listens: one that was free a moment ago.
quint16 closedPort() {
    QTcpServer probe;
    if (!probe.listen(QHostAddress::LocalHost))
        return 0;
    const quint16 port = probe.serverPort();
    probe.close();
    return port;
}

QByteArray joined(const QSignalSpy &spy) {
    QByteArray out;
    for (const QList<QVariant> &args : spy)
        out += args.at(0).toByteArray();
    return out;
}

qint64 summed(const QSignalSpy &spy) {
    qint64 n = 0;
    for (const QList<QVariant> &args : spy)
        n += args.at(0).toLongLong();
    return n;
}

// A TcpTransport to a loopback server, with every signal it gives recorded.
struct Link {
    Link()
        : t(QStringLiteral("127.0.0.1"), s.port()) {}

    // Opens the transport and takes the server's side of the connection; null if either failed
    // (or a signal could not be recorded).
    QTcpSocket *connect() {
        if (!spying())
            return nullptr;
        const qsizetype before = opened.count();
        t.open();
        if (!QTest::qWaitFor([&] { return opened.count() > before; }, kWaitMs))
            return nullptr;
        return s.accept();
    }
    [[nodiscard]] bool spying() const {
        return opened.isValid() && received.isValid() && written.isValid() && dropped.isValid() &&
               failed.isValid();
    }

    Server s;
    TcpTransport t;
    QSignalSpy opened{&t, &Transport::opened};
    QSignalSpy received{&t, &Transport::received};
    QSignalSpy written{&t, &Transport::bytesWritten};
    QSignalSpy dropped{&t, &Transport::disconnected};
    QSignalSpy failed{&t, &Transport::openFailed};
};

} // namespace

class TestTcpTransport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void opensToAListeningServer();
    void openingWhenOpenSaysOpenedAgainOnTheSameConnection();
    void sendsExactlyTheBytesAndSaysTheyWereWritten();
    void moreThanTheSocketTakesAtOnceGoesOutWholeAndInOrder();
    void handsOnWhatArrivesHoweverTheNetworkSplitsIt();
    void whatThePeerSentBeforeClosingIsStillReceived();
    void aPeerThatClosesIsADroppedLineWithTheReason();
    void aDroppedLineOpensAgain();
    void closingIsNotADrop();
    void writingWhileClosedSendsNothing();
    void aRefusedConnectionFailsTheOpenWithTheReason();
    void aHostThatDoesNotExistIsNotFound();
    void aConnectionNeverAcceptedFailsAfterTheConnectTimeout();
    void hostAndPortAreParsed_data();
    void hostAndPortAreParsed();
};

void TestTcpTransport::opensToAListeningServer() {
    Server s;
    TcpTransport t(QStringLiteral("127.0.0.1"), s.port(), 9600);
    QSignalSpy opened(&t, &Transport::opened);
    QVERIFY(opened.isValid());
    QVERIFY(!t.isOpen());
    t.open();
    QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, kWaitMs);
    QVERIFY(t.isOpen());
    QVERIFY(s.accept());
    QCOMPARE(t.description(), QStringLiteral("tcp 127.0.0.1:%1").arg(s.port()));
    QCOMPARE(t.baudRate(), 9600); // the serial wire's, for answer budgets
    QCOMPARE(TcpTransport(QStringLiteral("h"), 1).baudRate(), 19200);
}

void TestTcpTransport::openingWhenOpenSaysOpenedAgainOnTheSameConnection() {
    Link l;
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    l.t.open();
    QCOMPARE(l.opened.count(), 2);
    QTest::qWait(50); // a second connection would be pending by now
    QVERIFY(!l.s.server.hasPendingConnections());
    QCOMPARE(peer->state(), QAbstractSocket::ConnectedState);
}

void TestTcpTransport::sendsExactlyTheBytesAndSaysTheyWereWritten() {
    Link l;
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    const QByteArray first = Frame::read("SMN").addressed(0, 1).encode();
    const QByteArray second = Frame::write("MAT", "00375").addressed(0, 1).encode();
    l.t.write(first);
    l.t.write(second);
    QByteArray arrived;
    QTRY_VERIFY_WITH_TIMEOUT((arrived += peer->readAll()).size() >= first.size() + second.size(),
                             kWaitMs);
    QCOMPARE(arrived, first + second);
    QTRY_COMPARE_WITH_TIMEOUT(summed(l.written), qint64(first.size() + second.size()), kWaitMs);
}

// A request goes straight to the socket; what the socket cannot take yet (a peer that is not
// reading, a full buffer) waits in Qt's buffer, and what is written next goes after it.
void TestTcpTransport::moreThanTheSocketTakesAtOnceGoesOutWholeAndInOrder() {
    Link l;
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    QByteArray big(32 << 20, Qt::Uninitialized); // beyond any loopback socket's buffers
    for (qsizetype i = 0; i < big.size(); ++i)
        big[i] = char(i * 7 / 5);
    const QByteArray after = Frame::read("SMN").addressed(0, 1).encode();
    l.t.write(big);
    l.t.write(after);
    QByteArray arrived;
    QTRY_VERIFY_WITH_TIMEOUT((arrived += peer->readAll()).size() >= big.size() + after.size(),
                             kWaitMs);
    QVERIFY(arrived == big + after); // not QCOMPARE: 32 MB would be printed on a failure
    QTRY_COMPARE_WITH_TIMEOUT(summed(l.written), qint64(big.size() + after.size()), kWaitMs);
}

void TestTcpTransport::handsOnWhatArrivesHoweverTheNetworkSplitsIt() {
    Link l;
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    // An answer in three pieces, each flushed and left to arrive before the next.
    const Frame answer{1, 0, tipscope::protocol::Header::Answer, "SMN", "DME-2C"};
    const QByteArray bytes = answer.encode();
    const QList<QByteArray> pieces{bytes.left(1), bytes.mid(1, 6), bytes.mid(7)};
    QByteArray sent;
    for (const QByteArray &piece : pieces) {
        sent += piece;
        peer->write(piece);
        peer->flush();
        QTRY_COMPARE_WITH_TIMEOUT(joined(l.received), sent, kWaitMs);
    }
    QVERIFY(l.received.count() >= 3); // never held back waiting for more
    tipscope::protocol::FrameDecoder decoder;
    const auto events = decoder.feed(joined(l.received));
    QCOMPARE(events.size(), size_t(1));
    QCOMPARE(events.front().frame, answer);
}

void TestTcpTransport::whatThePeerSentBeforeClosingIsStillReceived() {
    Link l;
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    const QByteArray last = Frame{1, 0, tipscope::protocol::Header::Answer, "SVR", "1.0"}.encode();
    peer->write(last);
    peer->disconnectFromHost(); // writes what is pending, then closes
    QTRY_COMPARE_WITH_TIMEOUT(l.dropped.count(), 1, kWaitMs);
    QCOMPARE(joined(l.received), last);
}

void TestTcpTransport::aPeerThatClosesIsADroppedLineWithTheReason() {
    Link l;
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    peer->close();
    QTRY_COMPARE_WITH_TIMEOUT(l.dropped.count(), 1, kWaitMs);
    const QString reason = l.dropped.at(0).at(0).toString();
    QVERIFY2(reason.startsWith(
                 QStringLiteral("the connection to tcp 127.0.0.1:%1 dropped (").arg(l.s.port())),
             qPrintable(reason));
    QVERIFY2(reason.contains(QLatin1String("closed")), qPrintable(reason)); // the system's words
    QVERIFY(!l.t.isOpen());
    QTest::qWait(50);
    QCOMPARE(l.dropped.count(), 1); // once
    QCOMPARE(l.failed.count(), 0);
}

void TestTcpTransport::aDroppedLineOpensAgain() {
    Link l;
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    peer->close();
    QTRY_COMPARE_WITH_TIMEOUT(l.dropped.count(), 1, kWaitMs);

    l.s.peer = nullptr;
    QTcpSocket *again = l.connect(); // what Line does after a loss
    QVERIFY(again);
    again->write("\x06");
    QTRY_COMPARE_WITH_TIMEOUT(joined(l.received), QByteArray("\x06"), kWaitMs);
    // A second drop is reported as one too: the transport knows it was connected again.
    again->close();
    QTRY_COMPARE_WITH_TIMEOUT(l.dropped.count(), 2, kWaitMs);
}

void TestTcpTransport::closingIsNotADrop() {
    Link l;
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    l.t.close();
    QVERIFY(!l.t.isOpen());
    QTRY_COMPARE_WITH_TIMEOUT(peer->state(), QAbstractSocket::UnconnectedState, kWaitMs);
    QTest::qWait(50);
    QCOMPARE(l.dropped.count(), 0);
    QCOMPARE(l.failed.count(), 0);
}

void TestTcpTransport::writingWhileClosedSendsNothing() {
    Link l;
    l.t.write("never"); // before open: dropped by the transport, not queued for later
    QTcpSocket *peer = l.connect();
    QVERIFY(peer);
    l.t.write("now");
    QByteArray arrived;
    QTRY_VERIFY_WITH_TIMEOUT((arrived += peer->readAll()).size() >= 3, kWaitMs);
    QCOMPARE(arrived, QByteArray("now"));
    QTRY_COMPARE_WITH_TIMEOUT(summed(l.written), qint64(3), kWaitMs);
}

void TestTcpTransport::aRefusedConnectionFailsTheOpenWithTheReason() {
    const quint16 port = closedPort();
    QVERIFY(port != 0);
    TcpTransport t(QStringLiteral("127.0.0.1"), port);
    QSignalSpy opened(&t, &Transport::opened);
    QSignalSpy failed(&t, &Transport::openFailed);
    QSignalSpy dropped(&t, &Transport::disconnected);
    QVERIFY(opened.isValid() && failed.isValid() && dropped.isValid());
    t.open();
    QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, kWaitMs);
    QCOMPARE(failed.at(0).at(0).value<OpenFailure>(), OpenFailure::Other);
    const QString reason = failed.at(0).at(1).toString();
    QVERIFY2(reason.startsWith(QStringLiteral("cannot connect to tcp 127.0.0.1:%1: ").arg(port)),
             qPrintable(reason));
    QVERIFY2(reason.contains(QLatin1String("refused")), qPrintable(reason));
    QVERIFY(!t.isOpen());
    QCOMPARE(opened.count(), 0);
    QCOMPARE(dropped.count(), 0); // it never was open
}

void TestTcpTransport::aHostThatDoesNotExistIsNotFound() {
    // .invalid never resolves (RFC 6761); a machine without any name service says so at once.
    TcpTransport t(QStringLiteral("tipscope-test.invalid"), 4001);
    QSignalSpy failed(&t, &Transport::openFailed);
    QVERIFY(failed.isValid());
    t.open();
    QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 30000);
    QCOMPARE(failed.at(0).at(0).value<OpenFailure>(), OpenFailure::NotFound);
    const QString reason = failed.at(0).at(1).toString();
    QVERIFY2(reason.startsWith(QLatin1String("cannot connect to tcp tipscope-test.invalid:4001: ")),
             qPrintable(reason));
}

// A server whose accept queue is full held the open for the system's own limit, a minute and more.
void TestTcpTransport::aConnectionNeverAcceptedFailsAfterTheConnectTimeout() {
    tipscope::testing::FullBacklog listener;
    QVERIFY(listener.port() != 0);
    TcpTransport t(QStringLiteral("127.0.0.1"), listener.port());
    t.setConnectTimeoutMs(300);
    QSignalSpy opened(&t, &Transport::opened);
    QSignalSpy failed(&t, &Transport::openFailed);
    QVERIFY(opened.isValid() && failed.isValid());
    t.open();
    QVERIFY(failed.wait(kWaitMs));
    QCOMPARE(opened.count(), 0);
    const QString why = failed.first().at(1).toString();
    QVERIFY2(why.contains(QStringLiteral("no connection within 0.3 s")), qPrintable(why));
    QVERIFY(!t.isOpen());
    QTest::qWait(100);
    QCOMPARE(failed.count(), 1);
}

void TestTcpTransport::hostAndPortAreParsed_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<QString>("host");
    QTest::addColumn<int>("port");

    QTest::newRow("address and port") << "10.0.0.5:4001" << true << "10.0.0.5" << 4001;
    QTest::newRow("name and port") << "ser2net.local:2000" << true << "ser2net.local" << 2000;
    QTest::newRow("highest port") << "h:65535" << true << "h" << 65535;
    QTest::newRow("IPv6, the last colon ends the host") << "::1:4001" << true << "::1" << 4001;
    QTest::newRow("port 0") << "h:0" << false << "" << 0;
    QTest::newRow("port too high") << "h:65536" << false << "" << 0;
    QTest::newRow("negative port") << "h:-1" << false << "" << 0;
    QTest::newRow("no port") << "h" << false << "" << 0;
    QTest::newRow("empty port") << "h:" << false << "" << 0;
    QTest::newRow("no host") << ":4001" << false << "" << 0;
    QTest::newRow("port not a number") << "h:40a1" << false << "" << 0;
    QTest::newRow("nothing") << "" << false << "" << 0;
}

void TestTcpTransport::hostAndPortAreParsed() {
    QFETCH(QString, text);
    QFETCH(bool, ok);
    QFETCH(QString, host);
    QFETCH(int, port);
    QString parsedHost = QStringLiteral("untouched");
    quint16 parsedPort = 7;
    QCOMPARE(TcpTransport::parseHostPort(text, &parsedHost, &parsedPort), ok);
    if (ok) {
        QCOMPARE(parsedHost, host);
        QCOMPARE(int(parsedPort), port);
    } else { // a refusal leaves the caller's values alone
        QCOMPARE(parsedHost, QStringLiteral("untouched"));
        QCOMPARE(int(parsedPort), 7);
    }
}

TIPSCOPE_TEST_MAIN(TestTcpTransport)

} // namespace tst_tcptransport
#include "tst_tcptransport.moc"
