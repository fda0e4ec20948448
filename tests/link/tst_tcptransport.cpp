// TcpTransport against real TCP servers on the loopback interface: it connects, carries bytes both
// ways, reports a dropped connection, and gives up on a connection that is never made.
#include "fullbacklog.h"
#include "link/tcptransport.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QtTest>

using namespace tipscope::link;
using tipscope::testing::FullBacklog;

namespace {

constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on

} // namespace

class TestTcpTransport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void connectsAndCarriesBytesBothWays();
    void droppedConnectionIsReportedOnce();
    void refusedConnectionFailsWithTheReason();
    void connectionNeverAcceptedFailsAfterTheConnectTimeout();
};

void TestTcpTransport::connectsAndCarriesBytesBothWays() {
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost));
    TcpTransport t(QStringLiteral("127.0.0.1"), server.serverPort());
    QSignalSpy opened(&t, &Transport::opened);
    QSignalSpy received(&t, &Transport::received);
    QVERIFY(opened.isValid() && received.isValid());
    t.open();
    QVERIFY(opened.wait(kWaitMs));
    QVERIFY(t.isOpen());
    QTRY_VERIFY_WITH_TIMEOUT(server.hasPendingConnections(), kWaitMs);
    QTcpSocket *peer = server.nextPendingConnection();
    t.write("\x02R SMN\x03");
    QTRY_COMPARE_WITH_TIMEOUT(peer->bytesAvailable(), qint64(7), kWaitMs);
    peer->write("answer");
    QVERIFY(received.wait(kWaitMs));
    QCOMPARE(received.first().first().toByteArray(), QByteArray("answer"));
}

void TestTcpTransport::droppedConnectionIsReportedOnce() {
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost));
    TcpTransport t(QStringLiteral("127.0.0.1"), server.serverPort());
    QSignalSpy lost(&t, &Transport::disconnected);
    QVERIFY(lost.isValid());
    t.open();
    QTRY_VERIFY_WITH_TIMEOUT(server.hasPendingConnections(), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(t.isOpen(), kWaitMs);
    delete server.nextPendingConnection();
    QVERIFY(lost.wait(kWaitMs));
    QVERIFY2(lost.first().first().toString().contains(QStringLiteral("dropped")),
             qPrintable(lost.first().first().toString()));
    QTest::qWait(100);
    QCOMPARE(lost.count(), 1);
}

void TestTcpTransport::refusedConnectionFailsWithTheReason() {
    quint16 port = 0;
    {
        QTcpServer probe; // a port that was free a moment ago, and is closed now
        QVERIFY(probe.listen(QHostAddress::LocalHost));
        port = probe.serverPort();
    }
    TcpTransport t(QStringLiteral("127.0.0.1"), port);
    QSignalSpy failed(&t, &Transport::openFailed);
    QVERIFY(failed.isValid());
    t.open();
    QVERIFY(failed.wait(kWaitMs));
    QVERIFY2(failed.first().at(1).toString().contains(QStringLiteral("refused")),
             qPrintable(failed.first().at(1).toString()));
}

void TestTcpTransport::connectionNeverAcceptedFailsAfterTheConnectTimeout() {
    FullBacklog listener;
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

QTEST_GUILESS_MAIN(TestTcpTransport)
#include "tst_tcptransport.moc"
