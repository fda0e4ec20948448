// SimTransport, the demo's cable: it opens and carries a request to the simulated devices and
// their answer back, never from inside write(); a pulled cable is said and refused; and an answer
// that came in time is taken even when the thread was held up past the answer's budget, as it is
// on a real port whose bytes wait in the kernel.
#include "testmain.h"

#include "link/requestqueue.h"
#include "link/simtransport.h"
#include "protocol/frame.h"
#include "sim/simline.h"

#include <QSignalSpy>
#include <QTest>
#include <QThread>

namespace tst_simtransport {

using namespace tipscope::link;
using tipscope::protocol::Frame;
using tipscope::sim::SimLine;

namespace {

constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on

// The demo's line (a DME at 01, an SFR at 10), paced like a 19200-baud wire as the demo is.
struct DemoWire {
    DemoWire()
        : sim(SimLine::demo())
        , transport(*sim) {
        sim->paceLikeARealWire();
    }
    // Opens the transport and waits until it says so.
    bool open() {
        QSignalSpy opened(&transport, &Transport::opened);
        transport.open();
        return opened.wait(kWaitMs);
    }
    std::unique_ptr<SimLine> sim;
    SimTransport transport;
};

QByteArray joined(const QSignalSpy &spy) {
    QByteArray all;
    for (const QList<QVariant> &chunk : spy)
        all += chunk.first().toByteArray();
    return all;
}

} // namespace

class TestSimTransport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void opensAndCarriesARequestAndItsAnswer();
    void nothingIsHandedBackFromInsideWrite();
    void anAnswerThatCameInTimeIsTakenAfterTheThreadWasHeldUp();
    void anUnpluggedCableRefusesToOpen();
    void aPulledCableIsSaidAndStopsTheBytes();
    void theDescriptionNamesTheSimulatedDevices();
};

void TestSimTransport::opensAndCarriesARequestAndItsAnswer() {
    DemoWire w;
    QSignalSpy opened(&w.transport, &Transport::opened);
    QSignalSpy received(&w.transport, &Transport::received);
    w.transport.open();
    QVERIFY(!w.transport.isOpen()); // opening ends from the event loop
    QVERIFY(opened.wait(kWaitMs));
    QVERIFY(w.transport.isOpen());
    w.transport.write(Frame::read("SMN").addressed(0, 1).encode());
    QTRY_VERIFY_WITH_TIMEOUT(joined(received).contains("DME"), kWaitMs);
}

// A real port confirms a write and hands over its answer from the event loop; a queue written
// against the simulator must not come to rely on anything else.
void TestSimTransport::nothingIsHandedBackFromInsideWrite() {
    DemoWire w;
    QVERIFY(w.open());
    QSignalSpy written(&w.transport, &Transport::bytesWritten);
    QSignalSpy received(&w.transport, &Transport::received);
    const QByteArray request = Frame::read("SMN").addressed(0, 1).encode();
    w.transport.write(request);
    QCOMPARE(written.count(), 0);
    QCOMPARE(received.count(), 0);
    QVERIFY(written.wait(kWaitMs));
    QCOMPARE(written.first().first().toLongLong(), request.size());
}

// The demo's line runs in the window's thread. When that thread is held up longer than a
// request's answer budget (a page redrawn on a busy machine), the answer the station sent in time
// and the request's timer are both due when the loop runs again; the answer is the one taken,
// not a timeout that a person would read as a station that did not answer.
void TestSimTransport::anAnswerThatCameInTimeIsTakenAfterTheThreadWasHeldUp() {
    DemoWire w;
    RequestQueue queue;
    QueueSettings settings;
    settings.robotAddress = 0;
    settings.turnaroundMs = 20;
    settings.retries = 0; // a timeout would be final, not hidden by a retry
    queue.setSettings(settings);
    queue.setTransport(&w.transport);
    QVERIFY(w.open());
    queue.lineOpened();

    // Held up once the station has the request and its answer is on its way, with the queue's
    // timer for that answer started (its budget is well under 100 ms).
    QSignalSpy written(&w.transport, &Transport::bytesWritten);
    QObject owner;
    Reply *reply = queue.enqueue(Request::read(1, "SMN"), &owner);
    QVERIFY(written.wait(kWaitMs));
    QVERIFY(!reply->isFinished());
    QThread::msleep(400);
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kWaitMs);
    QVERIFY2(reply->error() == ReplyError::None, qPrintable(reply->errorString()));
    QVERIFY(reply->answer().data.contains("DME"));
    QCOMPARE(queue.stats().timeouts, 0);
}

void TestSimTransport::anUnpluggedCableRefusesToOpen() {
    DemoWire w;
    w.transport.setPlugged(false);
    QSignalSpy failed(&w.transport, &Transport::openFailed);
    w.transport.open();
    QVERIFY(failed.wait(kWaitMs));
    QCOMPARE(failed.first().at(0).value<OpenFailure>(), OpenFailure::NotFound);
    QCOMPARE(failed.first().at(1).toString(), QStringLiteral("the simulated line is unplugged"));
    QVERIFY(!w.transport.isOpen());

    w.transport.setPlugged(true);
    QVERIFY(w.open());
}

void TestSimTransport::aPulledCableIsSaidAndStopsTheBytes() {
    DemoWire w;
    QVERIFY(w.open());
    QSignalSpy lost(&w.transport, &Transport::disconnected);
    QSignalSpy received(&w.transport, &Transport::received);
    // Pulled with a request on its way: its answer never arrives.
    w.transport.write(Frame::read("SMN").addressed(0, 1).encode());
    w.transport.setPlugged(false);
    QCOMPARE(lost.count(), 1);
    QCOMPARE(lost.first().first().toString(), QStringLiteral("the simulated cable was pulled"));
    QVERIFY(!w.transport.isOpen());
    QTest::qWait(300); // several answers' worth of wire time
    QCOMPARE(received.count(), 0);
}

void TestSimTransport::theDescriptionNamesTheSimulatedDevices() {
    DemoWire w;
    QCOMPARE(w.transport.description(), QStringLiteral("demo (simulated DME + SFR)"));
    QCOMPARE(w.transport.baudRate(), 19200);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSimTransport)

} // namespace tst_simtransport

#include "tst_simtransport.moc"
