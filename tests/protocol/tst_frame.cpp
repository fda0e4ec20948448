// The guides' worked frames, byte-exact in both directions.
#include "protocol/framedecoder.h"
#include "testmain.h"

#include <QTest>

namespace tst_frame {

using namespace tipscope::protocol;

class TestFrame : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void guideFramesEncodeByteExact_data();
    void guideFramesEncodeByteExact();
    void guideFramesDecodeToTheirFields_data() { guideFramesEncodeByteExact_data(); }
    void guideFramesDecodeToTheirFields();
    void bccIsXorFromStxThroughEtx();
    void negativeAndTextDataSurviveRoundTrip();
    void toStringShowsAddressesHeaderCommandData();
};

static Frame makeFrame(std::optional<int> src, std::optional<int> tgt, const char *cmd,
                       const char *data) {
    Frame f = Frame::write(cmd, data);
    f.source = src;
    f.target = tgt;
    return f;
}

void TestFrame::guideFramesEncodeByteExact_data() {
    QTest::addColumn<Frame>("frame");
    QTest::addColumn<QByteArray>("hex");
    QTest::newRow("W MAT 00375 00->01")
        << makeFrame(0, 1, "MAT", "00375") << QByteArray("0230303031574D41543030333735033E");
    QTest::newRow("W MAT 00375 no addr")
        << makeFrame({}, {}, "MAT", "00375") << QByteArray("02574D41543030333735033F");
    QTest::newRow("W LEN 00200 00->10")
        << makeFrame(0, 10, "LEN", "00200") << QByteArray("0230303130574C454E30303230300322");
    QTest::newRow("W LEN 00200 no addr")
        << makeFrame({}, {}, "LEN", "00200") << QByteArray("02574C454E30303230300323");
}

void TestFrame::guideFramesEncodeByteExact() {
    QFETCH(Frame, frame);
    QFETCH(QByteArray, hex);
    QCOMPARE(frame.encode().toHex().toUpper(), hex);
}

void TestFrame::guideFramesDecodeToTheirFields() {
    QFETCH(Frame, frame);
    QFETCH(QByteArray, hex);
    FrameDecoder decoder;
    const auto events = decoder.feed(QByteArray::fromHex(hex));
    QCOMPARE(events.size(), size_t(1));
    QCOMPARE(events[0].kind, DecodeEvent::Kind::Frame);
    QCOMPARE(events[0].frame, frame);
    QCOMPARE(events[0].raw, QByteArray::fromHex(hex));
}

void TestFrame::bccIsXorFromStxThroughEtx() {
    const QByteArray body = QByteArray::fromHex("02574D41543030333735 03");
    QCOMPARE(quint8(blockCheck(body)), quint8(0x3F));
}

void TestFrame::negativeAndTextDataSurviveRoundTrip() {
    for (const Frame &f : {makeFrame(0, 1, "A12", "-0050"), makeFrame({}, {}, "SMN", "DDR"),
                           makeFrame(1, 0, "SVR", "9996780"), Frame::read("TT1").addressed(0, 1)}) {
        FrameDecoder d;
        const auto ev = d.feed(f.encode());
        QCOMPARE(ev.size(), size_t(1));
        QCOMPARE(ev[0].frame, f);
    }
}

void TestFrame::toStringShowsAddressesHeaderCommandData() {
    QCOMPARE(makeFrame(0, 1, "MAT", "00375").toString(), QStringLiteral("00→01 W MAT 00375"));
    QCOMPARE(Frame::read("ST1").toString(), QStringLiteral("R ST1"));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestFrame)

} // namespace tst_frame
#include "tst_frame.moc"
