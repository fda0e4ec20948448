// Scripted sessions with tipscope-sim through a real QSerialPort on a socat PTY pair, through
// the simulator's own PTY, and over TCP.
#include "ptyfixtures.h"
#include "testmain.h"

#include "protocol/framedecoder.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QSerialPort>
#include <QTcpSocket>
#include <QTest>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace tst_simserial {

using namespace tipscope::protocol;
using namespace tipscope::testing;

namespace {

struct Step {
    Frame request;
    QByteArray expectHeaderAndData; // e.g. "A00350", "N00003"; empty: expect silence
};

template <typename Device>
std::optional<Frame> exchange(Device &io, const Frame &request, int timeoutMs) {
    FrameDecoder decoder;
    io.write(request.encode());
    io.waitForBytesWritten(1000);
    const QDeadlineTimer deadline(timeoutMs);
    while (!deadline.hasExpired()) {
        if (!io.bytesAvailable() &&
            !io.waitForReadyRead(int(qMax<qint64>(1, deadline.remainingTime()))))
            continue;
        for (const auto &e : decoder.feed(io.readAll()))
            if (e.kind == DecodeEvent::Kind::Frame)
                return e.frame;
    }
    return std::nullopt;
}

Frame rd(const char *c, std::optional<int> target) {
    const Frame f = Frame::read(c);
    return target ? f.addressed(0, *target) : f;
}

Frame wr(const char *c, const char *d, std::optional<int> target) {
    const Frame f = Frame::write(c, d);
    return target ? f.addressed(0, *target) : f;
}

template <typename Device> void runScript(Device &io, const QList<Step> &steps) {
    for (const Step &s : steps) {
        const auto answer = exchange(io, s.request, s.expectHeaderAndData.isEmpty() ? 300 : 3000);
        const QString what = s.request.toString();
        if (s.expectHeaderAndData.isEmpty()) {
            QVERIFY2(!answer, qPrintable(what + QStringLiteral(": expected silence")));
            continue;
        }
        QVERIFY2(answer, qPrintable(what + QStringLiteral(": no answer")));
        QCOMPARE(answer->command, s.request.command);
        QCOMPARE(answer->source, s.request.target);
        QCOMPARE(answer->target, s.request.source);
        const QByteArray got = QByteArray(1, char(answer->header)) + answer->data;
        if (s.expectHeaderAndData.endsWith('*'))
            QVERIFY2(got.startsWith(s.expectHeaderAndData.chopped(1)),
                     qPrintable(what + ": " + got));
        else
            QCOMPARE(got, s.expectHeaderAndData);
    }
}

} // namespace

class TestSimSerial : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void dmeWithFourPortsAnswersAScriptedSession();
    void ddrWithoutAddressesAnswersAScriptedSession();
    void sfrAnswersTheGuidesWorkedFrame();
    void ownPtyServesAPlainSerialClient();
    void tcpServesRawFrames();
    void aChunkedPacedAnswerArrivesWhole();
    void tcpClientThatNeverReadsCostsABoundedBuffer();
    void pacedJunkDoesNotSilenceTheSimulator();
    void helpListsEveryCommandThePtySimulatorAccepts();
    void aLongCommandLineIsRefusedWholeNotSplit();

private:
    void withSocatSim(const QStringList &simArgs, const QList<Step> &script);
};

void TestSimSerial::withSocatSim(const QStringList &simArgs, const QList<Step> &script) {
    SocatPair pair;
    QString error;
    if (!pair.start(&error))
        QSKIP(qPrintable(error));
    SimProcess sim;
    QVERIFY2(!sim.start(simArgs + QStringList{QStringLiteral("--device"), pair.deviceEnd()}, &error)
                  .isEmpty(),
             qPrintable(error));
    QSerialPort port(pair.hostEnd());
    port.setBaudRate(QSerialPort::Baud19200);
    QVERIFY2(port.open(QIODevice::ReadWrite), qPrintable(port.errorString()));
    port.clear();
    runScript(port, script);
}

void TestSimSerial::dmeWithFourPortsAnswersAScriptedSession() {
    withSocatSim({QStringLiteral("--model"), QStringLiteral("DME")},
                 {
                     {rd("SMN", 1), "ADME-2C"},
                     {rd("SVR", 1), "A9996780"},
                     {rd("TT1", 1), "A*"},
                     {rd("TT4", 1), "A*"},
                     {rd("ST3", 1), "A00350"},
                     {wr("ST3", "00300", 1), "A"},
                     {rd("ST3", 1), "A00300"},
                     {wr("ST3", "00301", 1), "N00003"},
                     {rd("ST5", 1), "N00004"},
                     {wr("A41", "-0050", 1), "A"},
                     {rd("A41", 1), "A-0050"},
                     {rd("SMN", 10), ""},
                     {rd("SMN", std::nullopt), ""},
                 });
}

void TestSimSerial::ddrWithoutAddressesAnswersAScriptedSession() {
    withSocatSim({QStringLiteral("--model"), QStringLiteral("DDR")},
                 {
                     {rd("SMN", std::nullopt), "ADDR"},
                     {rd("PLM", std::nullopt), "A01000"},
                     {wr("PLM", "00800", std::nullopt), "A"},
                     {rd("PLM", std::nullopt), "A00800"},
                     {rd("MAT", std::nullopt), "A00400"},
                     {wr("ST1", "00455", std::nullopt), "N00003"},
                     {wr("PS2", "00010", std::nullopt), "N00003"},
                     {rd("SMN", 1), ""},
                 });
}

void TestSimSerial::sfrAnswersTheGuidesWorkedFrame() {
    const Frame guide = wr("LEN", "00200", 10);
    QCOMPARE(guide.encode().toHex().toUpper(), QByteArray("0230303130574C454E30303230300322"));
    withSocatSim({QStringLiteral("--model"), QStringLiteral("SFR")},
                 {
                     {rd("SMN", 10), "ASFR-A"},
                     {guide, "A00200"},
                     {rd("LEN", 10), "A00200"},
                     {wr("MOD", "00003", 10), "N00003"},
                     {wr("SFD", "00001", 10), "A00001"},
                     {rd("FDS", 10), "A00001"},
                     {wr("SSD", "00000", 10), "A00000"},
                     {wr("CTP", "00000", 10), "A00000"},
                     {rd("CTP", 10), "A00000"},
                 });
}

void TestSimSerial::ownPtyServesAPlainSerialClient() {
    SimProcess sim;
    QString error;
    const QString path = sim.start({QStringLiteral("--model"), QStringLiteral("DME"),
                                    QStringLiteral("--feeder"), QStringLiteral("--pty")},
                                   &error);
    QVERIFY2(path.startsWith(QStringLiteral("/dev/pts/")), qPrintable(error + path));
    QSerialPort port(path);
    QVERIFY2(port.open(QIODevice::ReadWrite), qPrintable(port.errorString()));
    port.clear();
    runScript(port, {{rd("SMN", 1), "ADME-2C"}, {rd("SMN", 10), "ASFR-A"}});
    QCOMPARE(sim.command(QStringLiteral("port-error 1 3")), QStringLiteral("ok"));
    runScript(port, {{rd("PE1", 1), "A00003"}});
}

// What help lists is accepted, and what the PTY simulator accepts beside SimControl's commands
// (unplug, plug) is listed. A bare listed verb may be refused for its missing arguments, never as
// an unknown command.
void TestSimSerial::helpListsEveryCommandThePtySimulatorAccepts() {
    SimProcess sim;
    QString error;
    const QString path = sim.start(
        {QStringLiteral("--model"), QStringLiteral("DME"), QStringLiteral("--feeder")}, &error);
    QVERIFY2(path.startsWith(QStringLiteral("/dev/pts/")), qPrintable(error + path));
    const QString help = sim.command(QStringLiteral("help"));
    QVERIFY2(help.startsWith(QStringLiteral("commands: ")), qPrintable(help));
    QStringList verbs;
    for (const QString &form : help.mid(10).split(QStringLiteral(" | ")))
        verbs.append(form.section(QLatin1Char(' '), 0, 0));
    for (const char *needed : {"port-error", "nak", "get", "stats", "help", "unplug", "plug"})
        QVERIFY2(verbs.contains(QLatin1String(needed)), qPrintable(needed + (": " + help)));
    for (const QString &verb : verbs) {
        const QString reply = sim.command(verb);
        QVERIFY2(!reply.startsWith(QStringLiteral("error: unknown command")),
                 qPrintable(verb + QStringLiteral(": ") + reply));
    }
}

void TestSimSerial::aLongCommandLineIsRefusedWholeNotSplit() {
    // Issue 38: a line past 1,023 bytes was cut at the read, and its rest ran as a command.
    SimProcess sim;
    QString error;
    QVERIFY2(!sim.start({QStringLiteral("--model"), QStringLiteral("DME")}, &error).isEmpty(),
             qPrintable(error));
    for (const int padding : {1023, 5000}) {
        const QString reply =
            sim.command(QString(padding, QLatin1Char('#')) + QStringLiteral("stats"));
        QVERIFY2(reply.startsWith(QStringLiteral("error: a command line longer than 1024 bytes")),
                 qPrintable(reply.left(200)));
        // The next reply is the next command's, not one of the long line's rest.
        const QString next = sim.command(QStringLiteral("get ST1"));
        QVERIFY2(next.startsWith(QStringLiteral("ST1=")), qPrintable(next.left(200)));
    }
}

void TestSimSerial::tcpServesRawFrames() {
    SimProcess sim;
    QString error;
    const QString where = sim.start({QStringLiteral("--model"), QStringLiteral("HDR"),
                                     QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")},
                                    &error);
    QVERIFY2(where.startsWith(QStringLiteral("127.0.0.1:")), qPrintable(error + where));
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), quint16(where.section(':', 1).toInt()));
    QVERIFY(socket.waitForConnected(3000));
    runScript(socket, {{rd("SMN", std::nullopt), "AHDR-2C"}, {rd("ST2", std::nullopt), "N00004"}});
}

// --chunk: a paced answer is handed over once it is in, as a device server packs a frame, not a
// byte at a time (a client wake-up a byte).
void TestSimSerial::aChunkedPacedAnswerArrivesWhole() {
    SimProcess sim;
    QString error;
    const QString where =
        sim.start({QStringLiteral("--model"), QStringLiteral("HDR"), QStringLiteral("--tcp"),
                   QStringLiteral("127.0.0.1:0"), QStringLiteral("--pace"), QStringLiteral("19200"),
                   QStringLiteral("--chunk"), QStringLiteral("200")},
                  &error);
    QVERIFY2(where.startsWith(QStringLiteral("127.0.0.1:")), qPrintable(error + where));
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), quint16(where.section(':', 1).toInt()));
    QVERIFY(socket.waitForConnected(3000));
    socket.write(rd("SMN", std::nullopt).encode());
    QVERIFY(socket.waitForReadyRead(3000));
    const QByteArray first = socket.readAll();
    FrameDecoder decoder;
    const auto events = decoder.feed(first);
    QVERIFY2(events.size() == 1 && events.front().kind == DecodeEvent::Kind::Frame,
             qPrintable(QString::fromLatin1(first.toHex(' '))));
    QCOMPARE(events.front().frame.header, Header::Answer);
    QCOMPARE(events.front().frame.data, QByteArray("HDR-2C"));
}

namespace {

// A loopback client with a tiny receive buffer that it never reads: what it is sent piles up on
// the sending side.
int connectNonReader(quint16 port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    const int tiny = 4096;
    ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &tiny, sizeof tiny);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(port);
    if (::connect(fd, reinterpret_cast<sockaddr *>(&a), sizeof a) != 0) {
        ::close(fd);
        return -1;
    }
    return fd;
}

// VmRSS of a process in KiB, from /proc; -1 when unreadable.
qint64 residentKiB(qint64 pid) {
    QFile f(QStringLiteral("/proc/%1/status").arg(pid));
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return -1;
    for (QByteArray line = f.readLine(); !line.isEmpty(); line = f.readLine())
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    return -1;
}

qint64 statsField(const QString &stats, const QString &name) {
    const QStringList words = stats.split(QLatin1Char(' '));
    const qsizetype at = words.indexOf(name);
    return at < 0 ? -1 : words.value(at + 1).toLongLong();
}

} // namespace

// Before, a client that sent requests and never read made the simulator buffer every answer
// (13 MB to 386 MB in 10 s), and a flood of requests was taken in whole, whatever its size.
void TestSimSerial::tcpClientThatNeverReadsCostsABoundedBuffer() {
    SimProcess sim;
    QString error;
    const QString where = sim.start({"--model", "DME", "--tcp", "127.0.0.1:0"}, &error);
    QVERIFY2(where.startsWith(QStringLiteral("127.0.0.1:")), qPrintable(error + where));
    const quint16 port = quint16(where.section(':', 1).toInt());
    const int fd = connectNonReader(port);
    QVERIFY(fd >= 0);
    QByteArray burst;
    for (int i = 0; i < 10000; ++i)
        burst += rd("ST1", 1).encode();
    const qint64 before = residentKiB(sim.process().processId());
    // Requests (110 kB a burst, 160 kB of answers) until the simulator drops answers it cannot
    // hand over, then as many more as would grow an unbounded buffer by 20 MB: sending a fixed
    // 33 MB took most of a minute under the sanitizers for the same proof.
    qint64 sent = 0;
    const auto sendBurst = [&] {
        const bool whole =
            ::send(fd, burst.constData(), size_t(burst.size()), 0) == ssize_t(burst.size());
        sent += whole ? burst.size() : 0;
        return whole;
    };
    qint64 unsent = 0;
    for (int i = 0; i < 300 && unsent == 0; ++i) {
        QVERIFY(sendBurst());
        unsent = statsField(sim.command("stats"), "unsent");
    }
    QVERIFY2(unsent > 0, "the simulator never dropped an answer for the client that never reads");
    for (int i = 0; i < 128; ++i)
        QVERIFY(sendBurst());
    // Every request read and answered (or its answer dropped) before the size is taken.
    QTRY_COMPARE_WITH_TIMEOUT(statsField(sim.command("stats"), "bytes-in"), sent, 60000);
    const qint64 grown = residentKiB(sim.process().processId()) - before;
    ::close(fd);
    // AddressSanitizer keeps freed memory in quarantine: there, the resident size says nothing.
    if (!qEnvironmentVariableIsSet("ASAN_OPTIONS"))
        QVERIFY2(grown < 16 * 1024, qPrintable(QStringLiteral("grew by %1 KiB").arg(grown)));

    // The next client is served as usual.
    QTcpSocket next;
    next.connectToHost(QStringLiteral("127.0.0.1"), port);
    QVERIFY(next.waitForConnected(3000));
    runScript(next, {{rd("SMN", 1), "ADME-2C"}});
}

// With --pace, 10 MB of junk pushed the simulated wire hours ahead, and nothing was answered again
// for any client. A receiver keeps a buffer; what comes faster than the wire beyond it is lost.
void TestSimSerial::pacedJunkDoesNotSilenceTheSimulator() {
    SimProcess sim;
    QString error;
    const QString where =
        sim.start({"--model", "DME", "--tcp", "127.0.0.1:0", "--pace", "19200"}, &error);
    QVERIFY2(where.startsWith(QStringLiteral("127.0.0.1:")), qPrintable(error + where));
    const quint16 port = quint16(where.section(':', 1).toInt());
    QTcpSocket junk;
    junk.connectToHost(QStringLiteral("127.0.0.1"), port);
    QVERIFY(junk.waitForConnected(3000));
    junk.write(QByteArray(10 << 20, 'x'));
    QTRY_VERIFY_WITH_TIMEOUT(junk.bytesToWrite() == 0 &&
                                 statsField(sim.command("stats"), "bytes-in") == (10 << 20),
                             30000);
    QVERIFY(statsField(sim.command("stats"), "overrun") >= (9 << 20));
    // The same client, once the buffer's 2 s of wire time have passed, and the next one.
    QTest::qWait(2500);
    runScript(junk, {{rd("SMN", 1), "ADME-2C"}});
    QTcpSocket next;
    next.connectToHost(QStringLiteral("127.0.0.1"), port);
    QVERIFY(next.waitForConnected(3000));
    runScript(next, {{rd("SVR", 1), "A9996780"}});
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSimSerial)

} // namespace tst_simserial
#include "tst_simserial.moc"
