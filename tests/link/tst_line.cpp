// A Line opens its transport, keeps requests flowing to the simulated devices, notices a lost or
// silent line, fails what was pending with the reason, and reopens by itself.
#include "link/line.h"
#include "link/serialtransport.h"
#include "link/simtransport.h"
#include "sim/simcontrol.h"
#include "sim/simline.h"
#include "testmain.h"

#include <QFile>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTest>

namespace tst_line {

using namespace tipscope::link;
using tipscope::sim::SimLine;

namespace {

constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on

LineSettings quickDemoSettings() {
    LineSettings s;
    s.kind = LineSettings::Kind::Demo;
    s.queue.turnaroundMs = 20;
    s.queue.retries = 0;
    s.reconnectIntervalMs = 50;
    s.suspectAfterTimeouts = 3;
    return s;
}

// A demo line with its transport kept at hand, to pull and plug the simulated cable.
struct DemoBench {
    explicit DemoBench(const LineSettings &settings = quickDemoSettings())
        : sim(SimLine::demo()) {
        auto t = std::make_unique<SimTransport>(*sim);
        transport = t.get();
        line = std::make_unique<Line>(std::move(t), settings);
    }

    Reply *read(const QByteArray &command, int target = 1) {
        return line->queue().enqueue(Request::read(target, command), &owner);
    }

    std::unique_ptr<SimLine> sim;
    SimTransport *transport = nullptr;
    std::unique_ptr<Line> line;
    QObject owner;
};

} // namespace

class TestLine : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void opensAndReadsFromTheSimulatedStation();
    void pulledCableFailsPendingRequestsAndTheLineReopensByItself();
    void consecutiveTimeoutsAreTakenForALostLine_data();
    void consecutiveTimeoutsAreTakenForALostLine();
    void retriesOfOneRequestAreNotTakenForALostLine();
    void closingWhileOpeningStaysClosed();
    void initialOpenFailureIsFinalUnlessRetryIsAsked_data();
    void initialOpenFailureIsFinalUnlessRetryIsAsked();
    void serialPortThatDoesNotExistFailsWithNotFound();
};

void TestLine::opensAndReadsFromTheSimulatedStation() {
    DemoBench b;
    QSignalSpy states(b.line.get(), &Line::stateChanged);
    QVERIFY(states.isValid());
    QCOMPARE(b.line->state(), Line::State::Closed);
    b.line->open();
    QCOMPARE(b.line->state(), Line::State::Opening);
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    QCOMPARE(states.count(), 2);
    QCOMPARE(states.at(1).at(0).value<Line::State>(), Line::State::Open);

    Reply *model = b.read("SMN");
    Reply *selected = b.read("ST1");
    Reply *feeder = b.read("SMN", 10);
    QTRY_VERIFY_WITH_TIMEOUT(model->isFinished() && selected->isFinished() && feeder->isFinished(),
                             kWaitMs);
    QVERIFY2(model->ok(), qPrintable(model->errorString()));
    QCOMPARE(model->answer().data, QByteArray("DME-2C"));
    QCOMPARE(model->answer().source, 1);
    QCOMPARE(selected->answer().data, QByteArray("00350"));
    QCOMPARE(feeder->answer().data, QByteArray("SFR-A"));
    QCOMPARE(b.line->reconnects(), 0);
}

void TestLine::pulledCableFailsPendingRequestsAndTheLineReopensByItself() {
    DemoBench b;
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);

    Reply *pending = b.read("SMN");
    QSignalSpy failed(pending, &Reply::finished);
    QVERIFY(failed.isValid());
    b.transport->setPlugged(false);
    QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, kWaitMs);
    QCOMPARE(pending->error(), ReplyError::Disconnected);
    QVERIFY2(pending->errorString().contains(QLatin1String("cable was pulled")),
             qPrintable(pending->errorString()));
    QCOMPARE(b.line->state(), Line::State::Retrying);
    QVERIFY(b.line->lastError().contains(QLatin1String("cable was pulled")));

    // While unplugged the line keeps trying and stays down; requests fail rather than wait.
    QTest::qWait(4 * quickDemoSettings().reconnectIntervalMs);
    QCOMPARE(b.line->state(), Line::State::Retrying);
    Reply *meanwhile = b.read("SMN");
    QTRY_VERIFY_WITH_TIMEOUT(meanwhile->isFinished(), kWaitMs);
    QCOMPARE(meanwhile->error(), ReplyError::NotOpen);

    b.transport->setPlugged(true);
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    QCOMPARE(b.line->reconnects(), 1);
    Reply *again = b.read("SMN");
    QTRY_VERIFY_WITH_TIMEOUT(again->isFinished(), kWaitMs);
    QVERIFY2(again->ok(), qPrintable(again->errorString()));
    QCOMPARE(again->answer().data, QByteArray("DME-2C"));
}

void TestLine::consecutiveTimeoutsAreTakenForALostLine_data() {
    QTest::addColumn<int>("suspectAfter");
    QTest::newRow("after 1") << 1;
    QTest::newRow("after 3") << 3;
    QTest::newRow("after 4") << 4;
}

void TestLine::consecutiveTimeoutsAreTakenForALostLine() {
    QFETCH(int, suspectAfter);

    LineSettings settings = quickDemoSettings();
    settings.suspectAfterTimeouts = suspectAfter;
    DemoBench b(settings);
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    QCOMPARE(tipscope::sim::executeSimCommand(*b.sim, QStringLiteral("drop 1.0")),
             QStringLiteral("ok"));

    const QList<QByteArray> commands{"ST1", "ST2", "ST3", "ST4"};
    for (int i = 0; i < suspectAfter - 1; ++i) {
        Reply *r = b.read(commands.at(i));
        QTRY_VERIFY_WITH_TIMEOUT(r->isFinished(), kWaitMs);
        QCOMPARE(r->error(), ReplyError::Timeout);
        QCOMPARE(b.line->state(), Line::State::Open); // not yet
    }
    QSignalSpy states(b.line.get(), &Line::stateChanged);
    QVERIFY(states.isValid());
    Reply *last = b.read(commands.at(suspectAfter - 1));
    QTRY_VERIFY_WITH_TIMEOUT(last->isFinished(), kWaitMs);
    QCOMPARE(last->error(), ReplyError::Timeout);
    QTRY_VERIFY_WITH_TIMEOUT(!states.isEmpty(), kWaitMs);
    QCOMPARE(states.at(0).at(0).value<Line::State>(), Line::State::Retrying);
    // The reason given with the drop: the line reopens 50 ms later, which clears lastError().
    const QString why = states.at(0).at(1).toString();
    QVERIFY2(why.contains(QStringLiteral("%1 requests in a row").arg(suspectAfter)),
             qPrintable(why));

    // The device comes back: the line reopens by itself and reads work again.
    QCOMPARE(tipscope::sim::executeSimCommand(*b.sim, QStringLiteral("drop 0")),
             QStringLiteral("ok"));
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    QCOMPARE(b.line->reconnects(), 1);
    Reply *again = b.read("SMN");
    QTRY_VERIFY_WITH_TIMEOUT(again->isFinished(), kWaitMs);
    QVERIFY2(again->ok(), qPrintable(again->errorString()));
}

void TestLine::retriesOfOneRequestAreNotTakenForALostLine() {
    // line.h: the line is suspected lost when `suspectAfterTimeouts` *requests* in a row get no
    // answer at all; one request and its retries are one request.
    LineSettings settings = quickDemoSettings();
    settings.queue.retries = 2;
    settings.suspectAfterTimeouts = 3;
    DemoBench b(settings);
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    QCOMPARE(tipscope::sim::executeSimCommand(*b.sim, QStringLiteral("drop 1.0")),
             QStringLiteral("ok"));

    Reply *r = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(r->isFinished(), kWaitMs);
    QCOMPARE(r->attempts(), 3);
    QCOMPARE(r->error(), ReplyError::Timeout); // not Disconnected
    QCOMPARE(b.line->state(), Line::State::Open);
}

void TestLine::closingWhileOpeningStaysClosed() {
    DemoBench b;
    QSignalSpy states(b.line.get(), &Line::stateChanged);
    QVERIFY(states.isValid());
    b.line->open();
    b.line->close(); // before the transport had a chance to report the outcome
    QCOMPARE(b.line->state(), Line::State::Closed);

    // Give a late opened() every chance to arrive; the user's close must stand.
    QTest::qWait(4 * quickDemoSettings().reconnectIntervalMs);
    QCOMPARE(b.line->state(), Line::State::Closed);
    QCOMPARE(states.count(), 2); // Opening, Closed
    Reply *r = b.read("SMN");
    QTRY_VERIFY_WITH_TIMEOUT(r->isFinished(), kWaitMs);
    QCOMPARE(r->error(), ReplyError::NotOpen);
}

void TestLine::initialOpenFailureIsFinalUnlessRetryIsAsked_data() {
    QTest::addColumn<bool>("retryInitialOpen");
    QTest::newRow("command-line default: give up") << false;
    QTest::newRow("retry initial open") << true;
}

void TestLine::initialOpenFailureIsFinalUnlessRetryIsAsked() {
    QFETCH(bool, retryInitialOpen);

    LineSettings settings = quickDemoSettings();
    settings.retryInitialOpen = retryInitialOpen;
    DemoBench b(settings);
    b.transport->setPlugged(false);
    b.line->open();
    QTRY_VERIFY_WITH_TIMEOUT(b.line->state() != Line::State::Opening, kWaitMs);
    QCOMPARE(b.line->state(), retryInitialOpen ? Line::State::Retrying : Line::State::Failed);
    QCOMPARE(b.line->lastFailure(), OpenFailure::NotFound);
    QVERIFY(b.line->stateText().contains(QLatin1String("unplugged")));

    b.transport->setPlugged(true);
    if (retryInitialOpen) {
        QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
        QCOMPARE(b.line->reconnects(), 0); // the first successful open is not a reconnect
    } else {
        QTest::qWait(4 * settings.reconnectIntervalMs);
        QCOMPARE(b.line->state(), Line::State::Failed);
    }
}

void TestLine::serialPortThatDoesNotExistFailsWithNotFound() {
    SerialSettings serial;
    // Unique per run: QSerialPort takes a lock file named after the port before opening it, and a
    // concurrent run holding that lock would turn NotFound into Permission.
    serial.portName = QStringLiteral("/dev/tipscope-test-no-such-port-%1-%2")
                          .arg(QCoreApplication::applicationPid())
                          .arg(QRandomGenerator::global()->generate());
    QVERIFY(!QFile::exists(serial.portName));
    auto transport = std::make_unique<SerialTransport>(serial);
    QSignalSpy openFailed(transport.get(), &Transport::openFailed);
    QVERIFY(openFailed.isValid());
    QSignalSpy opened(transport.get(), &Transport::opened);
    QVERIFY(opened.isValid());
    LineSettings settings;
    settings.serial = serial;
    Line line(std::move(transport), settings);

    line.open();
    QTRY_COMPARE_WITH_TIMEOUT(openFailed.count(), 1, kWaitMs);
    QCOMPARE(opened.count(), 0);
    QCOMPARE(openFailed.at(0).at(0).value<OpenFailure>(), OpenFailure::NotFound);
    const QString reason = openFailed.at(0).at(1).toString();
    QVERIFY(!reason.isEmpty());
    QCOMPARE(line.state(), Line::State::Failed);
    QCOMPARE(line.lastFailure(), OpenFailure::NotFound);
    QCOMPARE(line.lastError(), reason);
    QVERIFY(line.stateText().contains(reason));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestLine)

} // namespace tst_line
#include "tst_line.moc"
