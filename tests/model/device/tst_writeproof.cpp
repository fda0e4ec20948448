// WriteProof, the one proof of a write: a value the device holds is confirmed by one read; a first
// answer that differs is read once more and only the second decides; flags are compared by the
// digits that matter; a read-back without an answer says why; a data field that means nothing is
// no proof. Against the simulated station through the real queue.
#include "model/device/writeproof.h"
#include "model/simfixture.h"
#include "testmain.h"

#include "protocol/frame.h"

#include <QTest>

namespace tst_writeproof {

using namespace tipscope;
using namespace tipscope::model;
using protocol::Catalog;
using protocol::Direction;
using protocol::Frame;
using protocol::Header;
using testing::SimFixture;
using testing::singleDevice;

namespace {

constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on

// The proof of `written` for ST2 on the fixture's station, waited for; none if it never ended.
std::optional<WriteProof::Result> prove(SimFixture &f, const QByteArray &written) {
    const auto read = Catalog::builtin().resolve(QStringLiteral("DME"), "ST2", Direction::Read);
    std::optional<WriteProof::Result> result;
    WriteProof *proof = WriteProof::start(
        f.line->queue(), SimFixture::infoOf(*f.simLine->devices().first()).address, *read, written);
    QObject::connect(proof, &WriteProof::finished,
                     [&result](const WriteProof::Result &r) { result = r; });
    (void)QTest::qWaitFor([&result] { return result.has_value(); }, kWaitMs);
    return result;
}

// The station answers its first `staleReads` reads of ST2 with `old`, and `now` after them.
void answerStale(SimFixture &f, int staleReads, qint64 old, qint64 now, QObject *context) {
    sim::SimDevice *device = f.simLine->devices().first();
    auto reads = std::make_shared<int>(0);
    QObject::connect(f.simLine.get(), &sim::SimLine::requestReceived, context,
                     [device, reads, staleReads, old, now](const Frame &request) {
                         if (request.command != "ST2" || request.header != Header::Read)
                             return;
                         device->setSetting("ST2", ++*reads <= staleReads ? old : now);
                     });
}

} // namespace

class TestWriteProof : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aValueTheDeviceHoldsIsConfirmedByOneRead();
    void aFirstAnswerThatDiffersIsReadOnceMore_data();
    void aFirstAnswerThatDiffersIsReadOnceMore();
    void flagsAreComparedByTheDigitsThatMatter_data();
    void flagsAreComparedByTheDigitsThatMatter();
    void aReadBackWithoutAnAnswerSaysWhy();
    void aDataFieldThatMeansNothingIsNoProof();
};

void TestWriteProof::aValueTheDeviceHoldsIsConfirmedByOneRead() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    f.simLine->devices().first()->setSetting("ST2", 300);
    const std::optional<WriteProof::Result> r = prove(f, "00300");
    QVERIFY(r);
    QVERIFY(r->confirmed);
    QCOMPARE(r->reads, 1);
    QCOMPARE(r->reported, QByteArray("00300"));
    QCOMPARE(r->error, link::ReplyError::None);
}

void TestWriteProof::aFirstAnswerThatDiffersIsReadOnceMore_data() {
    QTest::addColumn<int>("staleReads");
    QTest::addColumn<bool>("confirmed");
    QTest::addColumn<QByteArray>("reported");
    // The late answer of a read from before the write, then the device's own.
    QTest::newRow("one stale answer") << 1 << true << QByteArray("00300");
    QTest::newRow("the device keeps the old value") << 1000 << false << QByteArray("00350");
}

void TestWriteProof::aFirstAnswerThatDiffersIsReadOnceMore() {
    QFETCH(int, staleReads);
    QFETCH(bool, confirmed);
    QFETCH(QByteArray, reported);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    QObject context;
    answerStale(f, staleReads, 350, 300, &context);
    const std::optional<WriteProof::Result> r = prove(f, "00300");
    QVERIFY(r);
    QCOMPARE(r->confirmed, confirmed);
    QCOMPARE(r->reads, 2);
    QCOMPARE(r->reported, reported);
}

void TestWriteProof::flagsAreComparedByTheDigitsThatMatter_data() {
    QTest::addColumn<qint64>("written");
    QTest::addColumn<qint64>("read");
    QTest::addColumn<bool>("confirms");
    // The ones digit is the status (0 working, 1 stand, 2 sleep, 3 hibernation), the tens
    // cooling, which a write sets; suction and the motor beyond are the station's own doing.
    QTest::newRow("working, read working") << qint64(0) << qint64(0) << true;
    QTest::newRow("working, read in the stand") << qint64(0) << qint64(1) << false;
    QTest::newRow("cooling, read cooling") << qint64(10) << qint64(10) << true;
    QTest::newRow("stand, read in the stand") << qint64(1) << qint64(1) << true;
    QTest::newRow("stand, moved on to sleep") << qint64(1) << qint64(2) << true;
    QTest::newRow("stand, moved on to hibernation") << qint64(1) << qint64(3) << true;
    QTest::newRow("sleep, read in the stand") << qint64(2) << qint64(1) << false;
    QTest::newRow("cooling not taken") << qint64(11) << qint64(1) << false;
    QTest::newRow("suction on besides") << qint64(11) << qint64(111) << true;
}

void TestWriteProof::flagsAreComparedByTheDigitsThatMatter() {
    QFETCH(qint64, written);
    QFETCH(qint64, read);
    QFETCH(bool, confirms);
    const auto status = Catalog::builtin().resolve(QStringLiteral("DME"), "PS1", Direction::Read);
    QVERIFY(status);
    QCOMPARE(WriteProof::confirms(*status, protocol::Value::ofNumber(written),
                                  protocol::Value::ofNumber(read)),
             confirms);
    // A number is the number it is.
    const auto setpoint = Catalog::builtin().resolve(QStringLiteral("DME"), "ST2", Direction::Read);
    QCOMPARE(WriteProof::confirms(*setpoint, protocol::Value::ofNumber(written),
                                  protocol::Value::ofNumber(read)),
             written == read);
}

void TestWriteProof::aReadBackWithoutAnAnswerSaysWhy() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    f.transport->setPlugged(false);
    const std::optional<WriteProof::Result> r = prove(f, "00300");
    QVERIFY(r);
    QVERIFY(!r->confirmed);
    QCOMPARE(r->reads, 1);
    QVERIFY(r->error != link::ReplyError::None);
    QVERIFY(!r->errorString.isEmpty());
    QVERIFY(r->reported.isEmpty());
}

// The written field decodes to nothing: whatever the device answers proves nothing, and is not
// read twice hoping it will.
void TestWriteProof::aDataFieldThatMeansNothingIsNoProof() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    const std::optional<WriteProof::Result> r = prove(f, "3x0");
    QVERIFY(r);
    QVERIFY(!r->confirmed);
    QCOMPARE(r->reads, 1);
    QCOMPARE(r->error, link::ReplyError::None);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestWriteProof)

} // namespace tst_writeproof

#include "tst_writeproof.moc"
