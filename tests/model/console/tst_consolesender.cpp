// The console's way onto the line, against the simulated DME at 01 and feeder at 10: what is sent
// reaches the device once and its answer is reported; monitor-only refuses whatever is or may be
// a write, says why, and puts nothing on the wire; without a line nothing is sent either.
#include "model/simfixture.h"
#include "testmain.h"

#include "i18n/translations.h"
#include "model/console/consolesender.h"
#include "model/console/framecomposer.h"
#include "protocol/hexbytes.h"

namespace tst_consolesender {

using namespace tipscope;
using model::ConsoleSender;
using protocol::Frame;
using testing::SimFixture;

namespace {
constexpr int kAnswerMs = 10000; // a ceiling for "eventually", never asserted on

QByteArray hex(const QString &text) {
    const auto bytes = protocol::parseHexBytes(text);
    return bytes.ok() ? bytes.value() : QByteArray();
}

// The demo line with a sender on it, and what the sender reported.
struct Bench {
    SimFixture f{sim::SimLine::demo()};
    ConsoleSender sender;
    QSignalSpy outcome{&sender, &ConsoleSender::outcome};
    qint64 sentBefore = 0;

    Bench() {
        sender.attach(&f.line->queue());
        sentBefore = sent();
    }
    [[nodiscard]] qint64 sent() const { return f.line->queue().stats().sent; }
};

// The outcomes reported so far, as text.
QStringList texts(const QSignalSpy &spy) {
    QStringList out;
    for (const QList<QVariant> &args : spy)
        out.append(args.at(0).toString());
    return out;
}
} // namespace

class TestConsoleSender : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void theExampleReadReachesTheDeviceOnceAndItsAnswerIsReported();
    void aComposedWriteChangesTheDevice();
    void aGarbledFrameIsSentOnceAndTheNakIsReported();
    void monitorOnlyRefusesWhatIsOrMayBeAWrite_data();
    void monitorOnlyRefusesWhatIsOrMayBeAWrite();
    void withoutALineNothingIsSentAndItSaysSo();
    void aLineThatIsGoneIsNotUsed();
    void theGateSaysWhenMonitorOnlyOrTheLineChanges();
};

void TestConsoleSender::initTestCase() {
    // English counts ("11 raw bytes") come from the English plurals catalogue, as in the programs.
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("en")),
             QStringLiteral("en"));
}

void TestConsoleSender::theExampleReadReachesTheDeviceOnceAndItsAnswerIsReported() {
    Bench b;
    QVERIFY(b.outcome.isValid());

    QVERIFY(b.sender.send(hex(model::FrameComposer::exampleHex())));
    QCOMPARE(b.outcome.count(), 1);
    QVERIFY2(b.outcome.at(0).at(0).toString().contains(QLatin1String("waiting for the answer")),
             qPrintable(texts(b.outcome).join(QLatin1Char('\n'))));
    QCOMPARE(b.outcome.at(0).at(1).toBool(), false);
    QTRY_COMPARE_WITH_TIMEOUT(b.outcome.count(), 2, kAnswerMs);
    const QString answer = b.outcome.at(1).at(0).toString();
    QVERIFY2(answer.startsWith(QStringLiteral("00→01 R SMN: answered 01→00 A SMN DME-2C after ")),
             qPrintable(answer));
    QCOMPARE(b.outcome.at(1).at(1).toBool(), false);
    QCOMPARE(b.sent(), b.sentBefore + 1);
}

void TestConsoleSender::aComposedWriteChangesTheDevice() {
    Bench b;
    QVERIFY(b.outcome.isValid());

    QVERIFY(b.sender.send(Frame::write("MAT", "00450").addressed(b.sender.robotAddress(), 1)));
    QTRY_COMPARE_WITH_TIMEOUT(b.outcome.count(), 2, kAnswerMs);
    QVERIFY2(b.outcome.at(1).at(0).toString().contains(QLatin1String("answered")),
             qPrintable(b.outcome.at(1).at(0).toString()));
    QCOMPARE(b.f.simLine->station()->setting("MAT"), std::optional<qint64>(450));
}

void TestConsoleSender::aGarbledFrameIsSentOnceAndTheNakIsReported() {
    Bench b;
    QVERIFY(b.outcome.isValid());

    // The read of the model name with a wrong BCC: the device answers NAK 00001, which the queue
    // would retry for its own requests. What a person typed goes out once.
    QVERIFY(b.sender.send(hex(QStringLiteral("02 30 30 30 31 52 53 4D 4E 03 5E"))));
    QTRY_COMPARE_WITH_TIMEOUT(b.outcome.count(), 2, kAnswerMs);
    const QString nak = b.outcome.at(1).at(0).toString();
    QVERIFY2(nak.startsWith(QLatin1String("11 raw bytes: refused, ")), qPrintable(nak));
    QCOMPARE(b.outcome.at(1).at(1).toBool(), true);
    QCOMPARE(b.sent(), b.sentBefore + 1);
}

void TestConsoleSender::monitorOnlyRefusesWhatIsOrMayBeAWrite_data() {
    QTest::addColumn<bool>("composed"); // a composed frame, or bytes as typed
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<bool>("refused");

    const QByteArray read = Frame::read("SMN").addressed(0, 1).encode();
    const QByteArray write = Frame::write("MAT", "00450").addressed(0, 1).encode();
    QTest::newRow("composed W frame") << true << write << true;
    QTest::newRow("typed W frame") << false << write << true;
    QTest::newRow("typed bytes that are no frame") << false << QByteArray("\x02W", 2) << true;
    QTest::newRow("typed frame with a wrong BCC") << false << read.chopped(1) + '^' << true;
    QTest::newRow("composed R frame") << true << read << false;
    QTest::newRow("typed R frame") << false << read << false;
}

void TestConsoleSender::monitorOnlyRefusesWhatIsOrMayBeAWrite() {
    QFETCH(bool, composed);
    QFETCH(QByteArray, bytes);
    QFETCH(bool, refused);

    Bench b;
    QVERIFY(b.outcome.isValid());
    b.sender.setMonitorOnly(true);

    const auto frame = protocol::parseFrame(bytes);
    QVERIFY(!composed || frame);
    const QString why = composed ? b.sender.refusal(*frame) : b.sender.refusal(bytes);
    QCOMPARE(why.isEmpty(), !refused);
    if (refused)
        QVERIFY2(why.startsWith(QLatin1String("Monitor-only mode is on: ")), qPrintable(why));
    const bool sent = composed ? b.sender.send(*frame) : b.sender.send(bytes);
    QCOMPARE(sent, !refused);
    QVERIFY(!b.outcome.isEmpty());
    const QString said = b.outcome.at(0).at(0).toString();
    QCOMPARE(said.endsWith(QLatin1String(": not sent, monitor-only mode is on")), refused);
    QCOMPARE(b.outcome.at(0).at(1).toBool(), refused);
    if (!refused) {
        QTRY_COMPARE_WITH_TIMEOUT(b.outcome.count(), 2, kAnswerMs);
        QCOMPARE(b.sent(), b.sentBefore + 1);
        return;
    }
    b.f.settle();
    QTest::qWait(100); // anything queued would have been written by now
    QCOMPARE(b.sent(), b.sentBefore);
    QCOMPARE(b.outcome.count(), 1);

    // The same off monitor-only goes out, so the refusal above is the gate's.
    b.sender.setMonitorOnly(false);
    QVERIFY(b.sender.refusal(bytes).isEmpty());
    QVERIFY(composed ? b.sender.send(*frame) : b.sender.send(bytes));
    QTRY_COMPARE_WITH_TIMEOUT(b.sent(), b.sentBefore + 1, kAnswerMs);
}

void TestConsoleSender::withoutALineNothingIsSentAndItSaysSo() {
    ConsoleSender sender;
    QSignalSpy outcome(&sender, &ConsoleSender::outcome);
    QVERIFY(outcome.isValid());
    QVERIFY(!sender.isAttached());
    QCOMPARE(sender.robotAddress(), 0);
    QVERIFY(!sender.send(Frame::read("SMN").addressed(0, 1)));
    QCOMPARE(outcome.count(), 1);
    QCOMPARE(outcome.at(0).at(0).toString(),
             QStringLiteral("00→01 R SMN: not sent, not connected"));
    QCOMPARE(outcome.at(0).at(1).toBool(), true);
}

void TestConsoleSender::aLineThatIsGoneIsNotUsed() {
    ConsoleSender sender;
    {
        SimFixture f(sim::SimLine::demo());
        sender.attach(&f.line->queue());
        QVERIFY(sender.isAttached());
    }
    QVERIFY(!sender.isAttached());
    QSignalSpy outcome(&sender, &ConsoleSender::outcome);
    QVERIFY(outcome.isValid());
    QVERIFY(!sender.send(hex(model::FrameComposer::exampleHex())));
    QVERIFY(outcome.at(0).at(0).toString().endsWith(QLatin1String("not sent, not connected")));
}

void TestConsoleSender::theGateSaysWhenMonitorOnlyOrTheLineChanges() {
    SimFixture f(sim::SimLine::demo());
    ConsoleSender sender;
    QSignalSpy gate(&sender, &ConsoleSender::gateChanged);
    QVERIFY(gate.isValid());
    sender.attach(&f.line->queue());
    QCOMPARE(gate.count(), 1);
    sender.setMonitorOnly(true);
    QCOMPARE(gate.count(), 2);
    sender.setMonitorOnly(true); // no change, no signal
    QCOMPARE(gate.count(), 2);
    sender.setMonitorOnly(false);
    QCOMPARE(gate.count(), 3);
}

TIPSCOPE_TEST_MAIN(TestConsoleSender)

} // namespace tst_consolesender
#include "tst_consolesender.moc"
