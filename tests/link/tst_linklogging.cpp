// The logging categories are switched by rules alone: tipscope.link.hex prints every byte only
// when asked, tipscope.link tells retries and line states, tipscope.protocol every skipped
// malformed frame; with no rules, none of them prints anything.
#include "link/line.h"
#include "link/requestqueue.h"
#include "link/simtransport.h"
#include "protocol/framedecoder.h"
#include "sim/simline.h"
#include "testmain.h"

#include <QLoggingCategory>
#include <QSignalSpy>
#include <QTest>

namespace tst_linklogging {

using namespace tipscope::link;
using tipscope::protocol::FrameDecoder;
using tipscope::sim::SimLine;

namespace {

constexpr int kWaitMs = 20000; // a generous ceiling for "eventually", never asserted on

QStringList g_messages; // "category: message", as the handler received them

void capture(QtMsgType, const QMessageLogContext &context, const QString &message) {
    g_messages.append(QStringLiteral("%1: %2").arg(QLatin1String(context.category), message));
}

QStringList messagesOf(const QString &category) {
    QStringList out;
    const QString prefix = category + QStringLiteral(": ");
    for (const QString &m : std::as_const(g_messages))
        if (m.startsWith(prefix))
            out.append(m.mid(prefix.size()));
    return out;
}

// Asks the demo line's station for its model name and a silent address for anything; returns
// the bytes of the station's request as the hex log would show them.
QString exchangeOnDemoLine() {
    auto sim = SimLine::demo();
    LineSettings s;
    s.kind = LineSettings::Kind::Demo;
    s.queue.turnaroundMs = 20;
    Line line(std::make_unique<SimTransport>(*sim), s);
    line.open();
    if (!QTest::qWaitFor([&] { return line.state() == Line::State::Open; }, kWaitMs))
        return {};
    QObject owner;
    Reply *answered = line.queue().enqueue(Request::read(1, "SMN"), &owner);
    Reply *silent = line.queue().enqueue(Request::read(42, "SMN"), &owner);
    if (!QTest::qWaitFor([&] { return answered->isFinished() && silent->isFinished(); }, kWaitMs))
        return {};
    return QString::fromLatin1(answered->request().encode().toHex(' '));
}

} // namespace

class TestLinkLogging : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void rulesDecideWhatTheLinkLogs_data();
    void rulesDecideWhatTheLinkLogs();
    void decoderLogsEverySkippedFrameWhenSwitchedOn_data();
    void decoderLogsEverySkippedFrameWhenSwitchedOn();

private:
    QtMessageHandler m_previous = nullptr;
};

void TestLinkLogging::init() {
    g_messages.clear();
    m_previous = qInstallMessageHandler(capture);
}

void TestLinkLogging::cleanup() {
    qInstallMessageHandler(m_previous);
    QLoggingCategory::setFilterRules(QString());
}

void TestLinkLogging::rulesDecideWhatTheLinkLogs_data() {
    QTest::addColumn<QString>("rules");
    QTest::addColumn<bool>("hex");
    QTest::addColumn<bool>("link");

    QTest::newRow("no rules: silent") << QString() << false << false;
    QTest::newRow("hex only") << QStringLiteral("tipscope.link.hex.debug=true") << true << false;
    QTest::newRow("link without its bytes")
        << QStringLiteral("tipscope.link.debug=true") << false << true;
    QTest::newRow("both") << QStringLiteral(
                                 "tipscope.link.debug=true\ntipscope.link.hex.debug=true")
                          << true << true;
}

void TestLinkLogging::rulesDecideWhatTheLinkLogs() {
    QFETCH(QString, rules);
    QFETCH(bool, hex);
    QFETCH(bool, link);
    QLoggingCategory::setFilterRules(rules);

    const QString request = exchangeOnDemoLine();
    QVERIFY(!request.isEmpty());

    const QStringList bytes = messagesOf(QStringLiteral("tipscope.link.hex"));
    QCOMPARE(bytes.contains(QStringLiteral("TX ") + request), hex);
    QCOMPARE(std::any_of(bytes.cbegin(), bytes.cend(),
                         [](const QString &m) { return m.startsWith(QStringLiteral("RX ")); }),
             hex);
    const QString said = messagesOf(QStringLiteral("tipscope.link")).join(QLatin1Char('\n'));
    QCOMPARE(said.contains(QStringLiteral("retrying")), link);
    QCOMPARE(said.contains(QStringLiteral("giving up")), link);
    QCOMPARE(said.contains(QStringLiteral("reconnects: 0")), link);
}

void TestLinkLogging::decoderLogsEverySkippedFrameWhenSwitchedOn_data() {
    QTest::addColumn<QString>("rules");
    QTest::addColumn<int>("logged");

    QTest::newRow("no rules: silent") << QString() << 0;
    QTest::newRow("protocol on") << QStringLiteral("tipscope.protocol.debug=true") << 2;
    QTest::newRow("link rules leave it off") << QStringLiteral("tipscope.link*.debug=true") << 0;
}

void TestLinkLogging::decoderLogsEverySkippedFrameWhenSwitchedOn() {
    QFETCH(QString, rules);
    QFETCH(int, logged);
    QLoggingCategory::setFilterRules(rules);

    FrameDecoder decoder;
    // Noise, then a frame with a wrong BCC.
    const auto events = decoder.feed(QByteArray("xyz\x02"
                                                "A\x03\x7f",
                                                7));
    QCOMPARE(int(events.size()), 2);
    QCOMPARE(decoder.skipped(), 2);

    const QStringList said = messagesOf(QStringLiteral("tipscope.protocol"));
    QCOMPARE(said.size(), logged);
    if (logged > 0) {
        QVERIFY2(said.at(0).contains(QStringLiteral("78 79 7a")), qPrintable(said.at(0)));
        QVERIFY2(said.at(1).contains(QStringLiteral("02 41 03 7f")), qPrintable(said.at(1)));
    }
}

TIPSCOPE_TEST_GUILESS_MAIN(TestLinkLogging)

} // namespace tst_linklogging
#include "tst_linklogging.moc"
