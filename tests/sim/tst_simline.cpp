// The simulator answers as the guides say, in-process and deterministic.
#include "protocol/framedecoder.h"
#include "protocol/valuecodec.h"
#include "sim/simcontrol.h"
#include "sim/simline.h"
#include "testmain.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

namespace tst_simline {

using namespace tipscope::protocol;
using namespace tipscope::sim;

namespace {

// Sends one request into the line and returns what came back, decoded.
struct Wire {
    explicit Wire(SimLine &l)
        : line(l) {}
    SimLine &line;
    FrameDecoder decoder;
    QByteArray received;

    std::vector<DecodeEvent> exchange(const Frame &request, int waitMs = 0) {
        received.clear();
        auto c = QObject::connect(&line, &SimLine::transmit,
                                  [this](const QByteArray &b) { received += b; });
        line.receive(request.encode());
        if (waitMs > 0)
            QTest::qWait(waitMs);
        QObject::disconnect(c);
        return decoder.feed(received);
    }
    std::optional<Frame> ask(const Frame &request) {
        const auto ev = exchange(request);
        for (const auto &e : ev)
            if (e.kind == DecodeEvent::Kind::Frame)
                return e.frame;
        return std::nullopt;
    }
};

Frame rd(const char *cmd, std::optional<int> target = 1) {
    Frame f = Frame::read(cmd);
    if (target)
        f = f.addressed(0, *target);
    return f;
}

Frame wr(const char *cmd, const char *data, std::optional<int> target = 1) {
    Frame f = Frame::write(cmd, data);
    if (target)
        f = f.addressed(0, *target);
    return f;
}

int nakCode(const std::optional<Frame> &f) {
    return f && f->header == Header::Nak ? f->data.toInt() : -1;
}

} // namespace

class TestSimLine : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void readsAnswerFromTheAddressedDeviceWithSwappedAddresses();
    void framesForOtherAddressesGetSilence();
    void writesAreStoredAndAnsweredWithoutDataByStations();
    void feederEchoesWrittenData();
    void outOfRangeOrOffStepWritesAreNak3();
    void selectedTemperatureMustStayBetweenMitAndMat();
    void unknownCommandsAndForeignCommandsAreNak4();
    void badBccInARequestIsNak1AndMalformedIsNak2();
    void robotModeOffIsNak5();
    void sadSwitchesAddressAndAddressingMode();
    void ddrAnswersOnlyWithoutAddresses();
    void ddrAlarmFlagsClearWhenRead();
    void tipFollowsTheSetpointWithinPowerBudget();
    void aRequestCatchesTheRunningClockUpWithoutItsTimer();
    void standLeadsToSleepAfterTheDelayAndCounts();
    void coolingAndSuctionAreSeparateDigitsOfStatus();
    void feederFeedsTheSetLengthInDiscontinuousMode();
    void feederErrorBlocksFeedingUntilReset();
    void factoryResetRestoresDefaults();
    void nvsKeepsSelectedTemperatureAcrossRestart();
    void dropAndCorruptFaultsAreCountedAndVisible();
    void badDataFaultSpoilsReadValuesButNotTextOrWrites();
    void nakFaultCanBeLimitedToWritesOrOneCommand_data();
    void nakFaultCanBeLimitedToWritesOrOneCommand();
    void pacedJunkCostsAtMostTheReceiversBufferOfWireTime();
    void requestFaultsLoseOrGarbleTheRequestBeforeTheDeviceSeesIt();
    void getTellsTheStoredSettingsOffTheWire();
    void pacedAnswersTakeAtLeastTheWireTime();
    void chunkedAnswersArriveInFewerPiecesAtTheSameTime_data();
    void chunkedAnswersArriveInFewerPiecesAtTheSameTime();
    void controlCommandsInjectFaultsAndRefuseNonsense();
};

void TestSimLine::readsAnswerFromTheAddressedDeviceWithSwappedAddresses() {
    auto line = SimLine::demo();
    Wire w(*line);
    const auto a = w.ask(rd("SMN"));
    QVERIFY(a);
    QCOMPARE(a->header, Header::Answer);
    QCOMPARE(a->data, QByteArray("DME-2C"));
    QCOMPARE(a->source, 1);
    QCOMPARE(a->target, 0);
    const auto f = w.ask(rd("SMN", 10));
    QCOMPARE(f->data, QByteArray("SFR-A"));
    QCOMPARE(f->source, 10);
}

void TestSimLine::framesForOtherAddressesGetSilence() {
    auto line = SimLine::demo();
    Wire w(*line);
    QVERIFY(w.exchange(rd("SMN", 2)).empty());
    QVERIFY(w.exchange(rd("SMN", 20)).empty());
    QVERIFY(w.exchange(rd("SMN", std::nullopt)).empty()); // nobody is without addresses
}

void TestSimLine::writesAreStoredAndAnsweredWithoutDataByStations() {
    auto line = SimLine::demo();
    Wire w(*line);
    const auto a = w.ask(wr("ST2", "00380"));
    QCOMPARE(a->header, Header::Answer);
    QCOMPARE(a->command, QByteArray("ST2"));
    QVERIFY(a->data.isEmpty());
    QCOMPARE(w.ask(rd("ST2"))->data, QByteArray("00380"));
    QCOMPARE(w.ask(wr("A12", "-0050"))->header, Header::Answer);
    QCOMPARE(w.ask(rd("A12"))->data, QByteArray("-0050"));
    QCOMPARE(w.ask(wr("HD1", "01.60"))->header, Header::Answer);
    QCOMPARE(w.ask(rd("HD1"))->data, QByteArray("01.60"));
    QCOMPARE(w.ask(wr("D12", "99999"))->header, Header::Answer);
    QCOMPARE(w.ask(rd("D12"))->data, QByteArray("99999"));
    QCOMPARE(line->station()->acceptedWrites().size(), 4);
}

void TestSimLine::feederEchoesWrittenData() {
    auto line = SimLine::demo();
    Wire w(*line);
    QCOMPARE(w.ask(wr("LEN", "00150", 10))->data, QByteArray("00150"));
    QCOMPARE(w.ask(wr("ECV", "00000", 10))->data, QByteArray("00001"));
}

void TestSimLine::outOfRangeOrOffStepWritesAreNak3() {
    auto line = SimLine::demo();
    Wire w(*line);
    QCOMPARE(nakCode(w.ask(wr("ST1", "00353"))), 3);
    QCOMPARE(nakCode(w.ask(wr("A12", "00051"))), 3);
    QCOMPARE(nakCode(w.ask(wr("H12", "00007"))), 3);
    QCOMPARE(nakCode(w.ask(wr("D12", "00010"))), 3);
    QCOMPARE(nakCode(w.ask(wr("PS1", "00002"))), 3); // sleep is not selectable
    QCOMPARE(nakCode(w.ask(wr("NVS", "00001"))), 3);
    QCOMPARE(nakCode(w.ask(wr("THI", "00003", 10))), 3);
    QCOMPARE(w.ask(rd("ST1"))->data, QByteArray("00350"));
    QVERIFY(line->station()->acceptedWrites().isEmpty());
}

void TestSimLine::selectedTemperatureMustStayBetweenMitAndMat() {
    auto line = SimLine::demo();
    Wire w(*line);
    QCOMPARE(w.ask(wr("MAT", "00400"))->header, Header::Answer);
    QCOMPARE(nakCode(w.ask(wr("ST1", "00450"))), 3);
    QCOMPARE(w.ask(wr("ST1", "00400"))->header, Header::Answer);
    QCOMPARE(nakCode(w.ask(wr("MIT", "00405"))), 3);
}

void TestSimLine::unknownCommandsAndForeignCommandsAreNak4() {
    auto line = SimLine::demo();
    Wire w(*line);
    QCOMPARE(nakCode(w.ask(rd("XYZ"))), 4);
    QCOMPARE(nakCode(w.ask(rd("ST5"))), 4);          // the DME has 4 ports
    QCOMPARE(nakCode(w.ask(rd("PLM"))), 4);          // DDR/HDR only
    QCOMPARE(nakCode(w.ask(wr("TT1", "00100"))), 4); // read-only
    QCOMPARE(nakCode(w.ask(rd("ST1", 10))), 4);      // a feeder has no ports
}

void TestSimLine::badBccInARequestIsNak1AndMalformedIsNak2() {
    auto line = SimLine::demo();
    Wire w(*line);
    QByteArray bad = rd("ST1").encode();
    bad.back() = char(bad.back() ^ 1);
    QByteArray got;
    connect(line.get(), &SimLine::transmit, this, [&](const QByteArray &b) { got += b; });
    line->receive(bad);
    auto ev = w.decoder.feed(got);
    QCOMPARE(int(ev.size()), 1);
    QCOMPARE(ev[0].frame.header, Header::Nak);
    QCOMPARE(ev[0].frame.data, QByteArray("00001"));
    QCOMPARE(nakCode(w.ask(wr("ST1", "0350"))), 2);
    QCOMPARE(nakCode(w.ask(wr("ST1", "3x500"))), 2);
    QCOMPARE(nakCode(w.ask(wr("HD1", "1.600"))), 2);
}

void TestSimLine::robotModeOffIsNak5() {
    auto line = SimLine::demo();
    line->station()->setRobotMode(false);
    Wire w(*line);
    QCOMPARE(nakCode(w.ask(rd("ST1"))), 5);
    QCOMPARE(w.ask(rd("LEN", 10))->header, Header::Answer);
}

void TestSimLine::sadSwitchesAddressAndAddressingMode() {
    auto line = SimLine::demo();
    Wire w(*line);
    const auto a = w.ask(wr("SAD", "00007"));
    QCOMPARE(a->source, 1); // answered from the old address
    QVERIFY(w.exchange(rd("SMN", 1)).empty());
    QCOMPARE(w.ask(rd("SMN", 7))->data, QByteArray("DME-2C"));
    QCOMPARE(w.ask(wr("SAD", "00000", 7))->header, Header::Answer);
    const auto plain = w.ask(rd("SMN", std::nullopt));
    QVERIFY(plain);
    QVERIFY(!plain->isAddressed());
    QCOMPARE(nakCode(w.ask(wr("SAD", "00100", std::nullopt))), 3);
}

void TestSimLine::ddrAnswersOnlyWithoutAddresses() {
    SimLine line;
    line.addDevice(std::make_unique<SimStation>(QStringLiteral("DDR")));
    Wire w(line);
    QVERIFY(w.exchange(rd("SMN", 1)).empty());
    QCOMPARE(w.ask(rd("SMN", std::nullopt))->data, QByteArray("DDR"));
    QCOMPARE(w.ask(rd("PLM", std::nullopt))->data, QByteArray("01000"));
    QCOMPARE(nakCode(w.ask(rd("ST3", std::nullopt))), 4);
    QCOMPARE(nakCode(w.ask(rd("SVR", std::nullopt))), 4);
    QCOMPARE(w.ask(rd("MAT", std::nullopt))->data, QByteArray("00400"));
}

void TestSimLine::ddrAlarmFlagsClearWhenRead() {
    SimLine line;
    auto *st = static_cast<SimStation *>(
        line.addDevice(std::make_unique<SimStation>(QStringLiteral("DDR"))));
    Wire w(line);
    st->latchAlarm(1, 11);
    QCOMPARE(w.ask(rd("TA1", std::nullopt))->data, QByteArray("00011"));
    QCOMPARE(w.ask(rd("TA1", std::nullopt))->data, QByteArray("00000"));
    auto dme = SimLine::demo();
    Wire w2(*dme);
    dme->station()->latchAlarm(2, 1);
    QCOMPARE(w2.ask(rd("TA2"))->data, QByteArray("00001"));
    QCOMPARE(w2.ask(rd("TA2"))->data, QByteArray("00001"));
}

void TestSimLine::tipFollowsTheSetpointWithinPowerBudget() {
    auto line = SimLine::demo();
    SimStation *st = line->station();
    QCOMPARE(st->port(1).tip, SimStation::kAmbient);
    line->advance(500);
    QCOMPARE(st->port(1).power, 1000); // heating flat out
    line->advance(20000);
    QVERIFY(qAbs(st->port(1).tip - 350) < 2);
    QVERIFY(st->port(1).power > 0 && st->port(1).power < 1000);
    Wire w(*line);
    QVERIFY(qAbs(w.ask(rd("TT1"))->data.toInt() - 350) <= 2);
    w.ask(wr("ST1", "00200"));
    line->advance(30000);
    QVERIFY(qAbs(st->port(1).tip - 200) < 2);
}

// A polled line moves time with its requests, so the clock's timer need not wake the process;
// here the event loop never runs, so only the request can have moved the tip.
void TestSimLine::aRequestCatchesTheRunningClockUpWithoutItsTimer() {
    auto line = SimLine::demo();
    line->setTickMs(50);
    line->setClockRunning(true);
    Wire w(*line);
    QElapsedTimer wall;
    wall.start();
    while (wall.elapsed() < 300) {
    }
    QVERIFY(w.ask(rd("TT1"))->data.toInt() > int(SimStation::kAmbient) + 20);
    QVERIFY(line->station()->port(1).power > 0);
}

void TestSimLine::standLeadsToSleepAfterTheDelayAndCounts() {
    auto line = SimLine::demo();
    Wire w(*line);
    const int tool = line->station()->port(1).tool;
    const QByteArray d = "D1" + QByteArray::number(tool);
    QCOMPARE(w.ask(wr(d.constData(), "00001"))->header, Header::Answer);
    const int cycles = line->station()->port(1).sleepCycles;
    w.ask(wr("PS1", "00001"));
    line->advance(30000);
    QCOMPARE(w.ask(rd("PS1"))->data, QByteArray("00001"));
    QCOMPARE(w.ask(rd("ED1"))->data, QByteArray("00030"));
    line->advance(31000);
    QCOMPARE(w.ask(rd("PS1"))->data, QByteArray("00002"));
    QCOMPARE(line->station()->port(1).sleepCycles, cycles + 1);
    line->advance(10 * 60 * 1000 + 1000);
    QCOMPARE(w.ask(rd("PS1"))->data, QByteArray("00003"));
}

void TestSimLine::coolingAndSuctionAreSeparateDigitsOfStatus() {
    auto line = SimLine::demo();
    Wire w(*line);
    line->station()->setTool(3, 5); // DS360 desoldering iron
    w.ask(wr("PS3", "00000"));
    QCOMPARE(w.ask(rd("PS3"))->data, QByteArray("00100"));
    w.ask(wr("PS1", "00010"));
    QCOMPARE(w.ask(rd("PS1"))->data, QByteArray("00010"));
}

void TestSimLine::feederFeedsTheSetLengthInDiscontinuousMode() {
    auto line = SimLine::demo();
    Wire w(*line);
    w.ask(wr("MOD", "00002", 10));
    w.ask(wr("LEN", "00050", 10));
    w.ask(wr("SPD", "00100", 10));
    w.ask(wr("SFD", "00001", 10));
    QCOMPARE(w.ask(rd("FDS", 10))->data, QByteArray("00001"));
    line->advance(200);
    QCOMPARE(w.ask(rd("FDL", 10))->data, QByteArray("00020"));
    line->advance(1000);
    QCOMPARE(w.ask(rd("FDL", 10))->data, QByteArray("00050"));
    QCOMPARE(w.ask(rd("FDS", 10))->data, QByteArray("00000"));
}

void TestSimLine::feederErrorBlocksFeedingUntilReset() {
    auto line = SimLine::demo();
    Wire w(*line);
    line->feeder()->setError(3);
    QCOMPARE(w.ask(rd("ECV", 10))->data, QByteArray("00003"));
    w.ask(wr("SFD", "00001", 10));
    QCOMPARE(w.ask(rd("FDS", 10))->data, QByteArray("00000"));
    w.ask(wr("ECV", "00000", 10));
    QCOMPARE(w.ask(rd("ECV", 10))->data, QByteArray("00000"));
    w.ask(wr("SFD", "00001", 10));
    QCOMPARE(w.ask(rd("FDS", 10))->data, QByteArray("00001"));
}

void TestSimLine::factoryResetRestoresDefaults() {
    auto line = SimLine::demo();
    Wire w(*line);
    w.ask(wr("MAT", "00450"));
    w.ask(wr("A21", "00010"));
    w.ask(wr("RSP", "00000"));
    QCOMPARE(w.ask(rd("MAT"))->data, QByteArray("00500"));
    QCOMPARE(w.ask(rd("A21"))->data, QByteArray("00000"));
}

void TestSimLine::nvsKeepsSelectedTemperatureAcrossRestart() {
    auto line = SimLine::demo();
    Wire w(*line);
    w.ask(wr("ST1", "00300"));
    w.ask(wr("NVS", "00000"));
    w.ask(wr("ST1", "00320"));
    w.ask(wr("RST", "00000"));
    QCOMPARE(w.ask(rd("ST1"))->data, QByteArray("00300"));
}

void TestSimLine::dropAndCorruptFaultsAreCountedAndVisible() {
    auto line = SimLine::demo();
    SimFaults f;
    f.dropShare = 0.3;
    f.corruptShare = 0.3;
    f.seed = 42;
    line->setFaults(f);
    Wire w(*line);
    int good = 0, bad = 0, silent = 0;
    for (int i = 0; i < 300; ++i) {
        const auto ev = w.exchange(rd("ST1"));
        w.decoder.reset();
        if (ev.empty())
            ++silent;
        for (const auto &e : ev)
            (e.kind == DecodeEvent::Kind::Frame && e.frame.data == "00350" ? good : bad)++;
    }
    // A truncated answer is silent too, so silence is at least the drops.
    QVERIFY(line->stats().dropped > 50);
    QVERIFY(qint64(silent) >= line->stats().dropped);
    QVERIFY(line->stats().corrupted > 30);
    QVERIFY(bad > 0 && good > 100);
}

void TestSimLine::badDataFaultSpoilsReadValuesButNotTextOrWrites() {
    auto line = SimLine::demo();
    QCOMPARE(executeSimCommand(*line, "bad-data 1"), QStringLiteral("ok"));
    QCOMPARE(line->faults().badDataShare, 1.0);
    QVERIFY(executeSimCommand(*line, "bad-data 1.5").startsWith("error:"));
    Wire w(*line);
    const Catalog &cat = Catalog::builtin();
    for (const char *code : {"ST1", "HD1", "TT2"}) {
        const auto answer = w.ask(rd(code));
        QVERIFY(answer);
        QCOMPARE(answer->header, Header::Answer);
        const auto cmd = cat.resolve(QStringLiteral("DME"), code, Direction::Read);
        QVERIFY2(!decodeAnswer(*cmd, answer->data), code);
    }
    QCOMPARE(w.ask(rd("SMN"))->data, QByteArray("DME-2C"));
    QCOMPARE(w.ask(wr("ST1", "00400"))->header, Header::Answer);
    QCOMPARE(line->station()->setting("ST1"), 400);
    QCOMPARE(line->stats().badData, 3);
    QVERIFY(executeSimCommand(*line, "stats").contains(QStringLiteral(" bad-data 3 ")));
}

void TestSimLine::nakFaultCanBeLimitedToWritesOrOneCommand_data() {
    QTest::addColumn<QString>("command");
    QTest::addColumn<QList<int>>("naks"); // R-SMN, R-ST1, W-ST1, R-ST2, W-ST2
    QTest::newRow("all") << "nak 3" << QList<int>{3, 3, 3, 3, 3};
    QTest::newRow("all, said") << "nak 3 all" << QList<int>{3, 3, 3, 3, 3};
    QTest::newRow("writes") << "nak 3 writes" << QList<int>{-1, -1, 3, -1, 3};
    QTest::newRow("one command") << "nak 4 st1" << QList<int>{-1, 4, 4, -1, -1};
    QTest::newRow("off") << "nak 0 writes" << QList<int>{-1, -1, -1, -1, -1};
}

// With every request NAKed, identification fails too, so no write could be tried against it.
void TestSimLine::nakFaultCanBeLimitedToWritesOrOneCommand() {
    QFETCH(QString, command);
    QFETCH(QList<int>, naks);
    auto line = SimLine::demo();
    QCOMPARE(executeSimCommand(*line, command), QStringLiteral("ok"));
    Wire w(*line);
    const QList<Frame> requests{rd("SMN"), rd("ST1"), wr("ST1", "00400"), rd("ST2"),
                                wr("ST2", "00410")};
    QList<int> got;
    for (const Frame &r : requests)
        got.append(nakCode(w.ask(r)));
    QCOMPARE(got, naks);
    for (const char *bad : {"nak 3 reads", "nak 3 ST", "nak 3 ST1 ST2", "nak -1", "nak x"})
        QVERIFY2(executeSimCommand(*line, bad).startsWith("error:"), bad);
}

// A wire carries a byte at a time; a receiver keeps a buffer of what came faster. Before, 1 MB of
// junk from a client that writes faster than the wire pushed the simulated wire 9 minutes ahead
// (10 MB: hours), and nothing was answered until then.
void TestSimLine::pacedJunkCostsAtMostTheReceiversBufferOfWireTime() {
    auto line = SimLine::demo();
    line->setBaud(19200);
    QByteArray got;
    connect(line.get(), &SimLine::transmit, this, [&](const QByteArray &b) { got += b; });
    line->receive(QByteArray(1 << 20, 'x'));
    // A request that comes while the buffer is full is lost with the junk, so ask again, as a
    // client retries. 4096 bytes at 19200 baud are 2.1 s of wire time.
    QTimer again;
    connect(&again, &QTimer::timeout, this, [&] { line->receive(rd("SMN").encode()); });
    again.start(500);
    QTRY_VERIFY_WITH_TIMEOUT(got.contains("DME-2C"), 10000);
    QVERIFY(line->stats().overrunBytes >= (1 << 20) - 4096);
    QVERIFY(executeSimCommand(*line, "stats").contains(QStringLiteral(" overrun ")));
}

// "drop" loses the answer of a request the device carried out; these lose the request itself.
void TestSimLine::requestFaultsLoseOrGarbleTheRequestBeforeTheDeviceSeesIt() {
    auto line = SimLine::demo();
    Wire w(*line);
    QCOMPARE(executeSimCommand(*line, "drop-requests 1"), QStringLiteral("ok"));
    QVERIFY(!w.ask(wr("ST1", "00400")));
    QCOMPARE(line->stats().requestsLost, 1);
    QCOMPARE(line->stats().requests, 0);

    QCOMPARE(executeSimCommand(*line, "drop-requests 0"), QStringLiteral("ok"));
    QCOMPARE(executeSimCommand(*line, "corrupt-requests 1"), QStringLiteral("ok"));
    int naks = 0;
    for (int i = 0; i < 50; ++i) {
        w.decoder.reset();
        const auto answer = w.ask(wr("ST1", "00400"));
        QVERIFY(!answer || nakCode(answer) == 1);
        naks += answer ? 1 : 0;
    }
    QVERIFY2(naks > 25, qPrintable(QString::number(naks))); // mostly a BCC error, NAK 00001
    QCOMPARE(line->stats().requestsGarbled, 50);
    QCOMPARE(line->station()->setting("ST1"), 350);
    QVERIFY(executeSimCommand(*line, "stats").contains(" lost-requests 1 garbled-requests 50"));
}

void TestSimLine::getTellsTheStoredSettingsOffTheWire() {
    auto line = SimLine::demo();
    QCOMPARE(executeSimCommand(*line, "get ST1 a12 LEN"), QStringLiteral("ST1=350 A12=0 LEN=200"));
    line->station()->setSetting("ST1", 400);
    QCOMPARE(executeSimCommand(*line, "get st1"), QStringLiteral("ST1=400"));
    QVERIFY(executeSimCommand(*line, "get").contains(QStringLiteral("MAT=")));
    QVERIFY(executeSimCommand(*line, "get XYZ").startsWith("error:"));
}

void TestSimLine::pacedAnswersTakeAtLeastTheWireTime() {
    auto line = SimLine::demo();
    line->setBaud(19200);
    QByteArray got;
    QElapsedTimer t;
    connect(line.get(), &SimLine::transmit, this, [&](const QByteArray &b) { got += b; });
    const QByteArray req = rd("TT1").encode(); // 11 bytes
    t.start();
    line->receive(req);
    QTRY_COMPARE_WITH_TIMEOUT(got.size(), 16, 5000);
    // 27 bytes at 10 bits each and 19200 baud: 14 ms is the physical floor.
    QVERIFY2(t.elapsed() >= 13, qPrintable(QString::number(t.elapsed())));
}

void TestSimLine::chunkedAnswersArriveInFewerPiecesAtTheSameTime_data() {
    QTest::addColumn<int>("chunkMs");
    QTest::addColumn<int>("maxPieces");
    QTest::newRow("byte by byte") << 0 << 16;
    QTest::newRow("adapter latency 4 ms") << 4 << 3;
    QTest::newRow("adapter latency longer than the answer") << 20 << 1;
}

// A USB adapter's latency timer groups the bytes of an answer; the answer is whole, and never
// earlier than the wire allows.
void TestSimLine::chunkedAnswersArriveInFewerPiecesAtTheSameTime() {
    QFETCH(int, chunkMs);
    QFETCH(int, maxPieces);
    auto line = SimLine::demo();
    line->setBaud(19200);
    line->setChunkMs(chunkMs);
    QByteArray got;
    int pieces = 0;
    connect(line.get(), &SimLine::transmit, this, [&](const QByteArray &b) {
        got += b;
        ++pieces;
    });
    QElapsedTimer t;
    t.start();
    line->receive(rd("TT1").encode());
    QTRY_COMPARE_WITH_TIMEOUT(got.size(), 16, 5000);
    QVERIFY2(t.elapsed() >= 13, qPrintable(QString::number(t.elapsed())));
    QVERIFY2(pieces <= maxPieces, qPrintable(QString::number(pieces)));
    FrameDecoder decoder;
    const auto events = decoder.feed(got);
    QCOMPARE(events.size(), size_t(1));
    QCOMPARE(events.front().kind, DecodeEvent::Kind::Frame);
}

void TestSimLine::controlCommandsInjectFaultsAndRefuseNonsense() {
    auto line = SimLine::demo();
    QCOMPARE(executeSimCommand(*line, "port-error 2 3"), QStringLiteral("ok"));
    QCOMPARE(line->station()->port(2).error, 3);
    QCOMPARE(executeSimCommand(*line, "robot-mode off"), QStringLiteral("ok"));
    QVERIFY(!line->station()->robotMode());
    QCOMPARE(executeSimCommand(*line, "drop 0.5"), QStringLiteral("ok"));
    QCOMPARE(line->faults().dropShare, 0.5);
    QVERIFY(executeSimCommand(*line, "drop 5").startsWith("error:"));
    QVERIFY(executeSimCommand(*line, "port-error 9 1").startsWith("error:"));
    QVERIFY(executeSimCommand(*line, "launch rockets").startsWith("error:"));
    QVERIFY(executeSimCommand(*line, "stats").contains("requests"));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSimLine)

} // namespace tst_simline
#include "tst_simline.moc"
