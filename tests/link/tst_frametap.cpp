// FrameTap: each event carries its kind, its payload and two timestamps, wall clock and
// monotonic, in the order things happened; a request queue taps every byte it writes, every
// chunk it receives and every decode event (a stray frame marked as such), so the console sees
// the wire as it was.
#include "scriptedqueue.h"
#include "testmain.h"

#include "link/frametap.h"

#include <QDateTime>
#include <QTest>
#include <QThread>

namespace tst_frametap {

using namespace tipscope::link;
using tipscope::protocol::DecodeEvent;
using tipscope::protocol::Frame;
using tipscope::protocol::Header;
using tipscope::test::answerTo;
using tipscope::test::ScriptedQueue;
using tipscope::test::ScriptedTransport;
using tipscope::test::withBadBcc;

namespace {

constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on

// Everything a tap emits, in order.
struct Recorder {
    explicit Recorder(FrameTap &tap) {
        QObject::connect(&tap, &FrameTap::event, &context,
                         [this](const TapEvent &e) { events.append(e); });
    }
    [[nodiscard]] QList<TapEvent::Kind> kinds() const {
        QList<TapEvent::Kind> out;
        for (const TapEvent &e : events)
            out.append(e.kind);
        return out;
    }
    [[nodiscard]] QByteArray received() const {
        QByteArray out;
        for (const TapEvent &e : events)
            if (e.kind == TapEvent::Kind::Rx)
                out += e.bytes;
        return out;
    }
    QObject context;
    QList<TapEvent> events;
};

} // namespace

class TestFrameTap : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void eachKindCarriesItsPayload();
    void eventsAreStampedWithTheWallClockAndInOrder();
    void aQueueTapsEveryByteAndEveryDecodeEvent();
    void aTimeoutAndALostLineAreNoted();
};

void TestFrameTap::eachKindCarriesItsPayload() {
    FrameTap tap;
    Recorder r(tap);
    const QByteArray request = Frame::read("SMN").addressed(0, 1).encode();
    DecodeEvent frame;
    frame.frame = Frame{1, 0, Header::Answer, "SMN", "DME-2C"};
    frame.raw = frame.frame.encode();
    DecodeEvent broken;
    broken.kind = DecodeEvent::Kind::BccError;
    broken.raw = withBadBcc(frame.frame);
    broken.detail = QStringLiteral("BCC is 00, expected 01");

    tap.tx(request);
    tap.rx(frame.raw.left(4));
    tap.decoded(frame, true);
    tap.decoded(broken, false);
    tap.note(QStringLiteral("line open"));

    QCOMPARE(r.kinds(),
             QList<TapEvent::Kind>({TapEvent::Kind::Tx, TapEvent::Kind::Rx, TapEvent::Kind::Decoded,
                                    TapEvent::Kind::Decoded, TapEvent::Kind::Note}));
    QCOMPARE(r.events.at(0).bytes, request);
    QCOMPARE(r.events.at(1).bytes, frame.raw.left(4));
    QCOMPARE(r.events.at(2).decoded.frame, frame.frame);
    QCOMPARE(r.events.at(2).decoded.raw, frame.raw);
    QVERIFY(r.events.at(2).stray);
    QCOMPARE(r.events.at(3).decoded.kind, DecodeEvent::Kind::BccError);
    QCOMPARE(r.events.at(3).decoded.detail, broken.detail);
    QVERIFY(!r.events.at(3).stray);
    QCOMPARE(r.events.at(4).note, QStringLiteral("line open"));
    QVERIFY(r.events.at(4).bytes.isEmpty());
}

void TestFrameTap::eventsAreStampedWithTheWallClockAndInOrder() {
    FrameTap tap;
    Recorder r(tap);
    const qint64 before = QDateTime::currentMSecsSinceEpoch();
    tap.note(QStringLiteral("first"));
    QThread::msleep(20);
    tap.tx("x");
    const qint64 after = QDateTime::currentMSecsSinceEpoch();

    QCOMPARE(r.events.size(), 2);
    for (const TapEvent &e : std::as_const(r.events)) {
        QVERIFY2(
            e.wallMs >= before && e.wallMs <= after,
            qPrintable(QStringLiteral("%1 not in %2..%3").arg(e.wallMs).arg(before).arg(after)));
        QVERIFY(e.monotonicUs > 0);
    }
    // The monotonic stamps order the events and measure what passed between them (at least the
    // sleep: a lower bound, which no busy machine can break).
    QVERIFY(r.events.at(1).monotonicUs - r.events.at(0).monotonicUs >= 20000);
    QVERIFY(r.events.at(1).wallMs >= r.events.at(0).wallMs);
}

void TestFrameTap::aQueueTapsEveryByteAndEveryDecodeEvent() {
    ScriptedQueue line(0, 200);
    ScriptedTransport &transport = line.transport;
    Recorder r(line.queue.tap());

    // Before the answer: a frame from another device (stray) and two bytes of noise; then the
    // answer in two chunks; then, with nothing pending, a corrupted frame.
    const Frame request = Frame::read("ST1").addressed(0, 1);
    const QByteArray stray = answerTo(Frame::read("ST1").addressed(0, 10), "00300").encode();
    const QByteArray answer = answerTo(request, "00350").encode();
    const QByteArray corrupted = withBadBcc(answerTo(request, "00351"));
    connect(&transport, &ScriptedTransport::written, this, [&](const QByteArray &) {
        transport.answer(stray + "\x7f\x7f" + answer.left(5), 1);
        transport.answer(answer.mid(5), 2);
        transport.answer(corrupted, 3);
    });
    QObject owner;
    Reply *reply = line.queue.enqueue(Request::read(1, "ST1"), &owner);
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kWaitMs);
    QVERIFY2(reply->ok(), qPrintable(reply->errorString()));
    QTRY_COMPARE_WITH_TIMEOUT(r.received().size(),
                              stray.size() + 2 + answer.size() + corrupted.size(), kWaitMs);

    QCOMPARE(r.events.first().kind, TapEvent::Kind::Tx);
    QCOMPARE(r.events.first().bytes, request.encode());
    QCOMPARE(r.received(), stray + "\x7f\x7f" + answer + corrupted); // every byte, in order
    QList<TapEvent> decoded;
    for (const TapEvent &e : std::as_const(r.events))
        if (e.kind == TapEvent::Kind::Decoded)
            decoded.append(e);
    QCOMPARE(decoded.size(), 4);
    QCOMPARE(decoded.at(0).decoded.kind, DecodeEvent::Kind::Frame);
    QCOMPARE(decoded.at(0).decoded.raw, stray);
    QVERIFY(decoded.at(0).stray);
    QCOMPARE(decoded.at(1).decoded.kind, DecodeEvent::Kind::Garbage);
    QCOMPARE(decoded.at(1).decoded.raw, QByteArray("\x7f\x7f"));
    QCOMPARE(decoded.at(2).decoded.kind, DecodeEvent::Kind::Frame);
    QCOMPARE(decoded.at(2).decoded.frame, reply->answer());
    QVERIFY(!decoded.at(2).stray);
    QCOMPARE(decoded.at(3).decoded.kind, DecodeEvent::Kind::BccError);
    QCOMPARE(decoded.at(3).decoded.raw, corrupted);

    for (qsizetype i = 1; i < r.events.size(); ++i)
        QVERIFY(r.events.at(i).monotonicUs >= r.events.at(i - 1).monotonicUs);
}

void TestFrameTap::aTimeoutAndALostLineAreNoted() {
    ScriptedQueue line(0, 10); // the transport answers nothing
    Recorder r(line.queue.tap());
    QObject owner;
    Reply *reply = line.queue.enqueue(Request::read(1, "ST1"), &owner);
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kWaitMs);
    QCOMPARE(reply->error(), ReplyError::Timeout);
    line.queue.lineLost(QStringLiteral("cable pulled"));

    QStringList notes;
    for (const TapEvent &e : std::as_const(r.events))
        if (e.kind == TapEvent::Kind::Note)
            notes.append(e.note);
    QCOMPARE(notes.size(), 2);
    QVERIFY2(notes.at(0).startsWith(QStringLiteral("00→01 R ST1: no answer")),
             qPrintable(notes.at(0)));
    QCOMPARE(notes.at(1), QStringLiteral("line lost: cable pulled"));
}

TIPSCOPE_TEST_MAIN(TestFrameTap)

} // namespace tst_frametap
#include "tst_frametap.moc"
