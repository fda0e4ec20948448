// tipscope-sim: serves simulated JBC devices on a PTY, an existing serial device, or TCP.
// The first line on standard output is where a client connects; standard input takes the
// control commands of SimControl plus "unplug" and "plug" for the PTY.
#include "simendpoints.h"

#include "sim/simcontrol.h"
#include "sim/simline.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QSocketNotifier>
#include <QTextStream>

#include <cstdio>
#include <functional>
#include <memory>
#include <unistd.h>
#include <utility>

using namespace tipscope::sim;
using tipscope::protocol::Catalog;

namespace {

// A control command is a few words; a longer line is a mistake or an attack.
constexpr qsizetype kMaxCommandBytes = 1024;

struct Options {
    QString model = QStringLiteral("DME");
    bool feeder = false;
    bool noAddr = false;
    int address = -1;
    SimFaults faults;
    int pace = 0;
    int chunkMs = 0;
    bool robotModeOff = false;
    bool activity = false;
    int jointsPerMinute = 0;
    JointShapeSet jointShapes = *JointShapeSet::named(QStringLiteral("demo"));
};

QTextStream &out() {
    static QTextStream s(stdout);
    return s;
}

[[noreturn]] void die(const QString &message, int code = 1) {
    QTextStream(stderr) << "tipscope-sim: " << message << Qt::endl;
    std::exit(code);
}

double shareOption(const QCommandLineParser &p, const QString &name) {
    bool ok = true;
    const double v = p.isSet(name) ? p.value(name).toDouble(&ok) : 0.0;
    if (!ok || v < 0 || v > 1)
        die(QStringLiteral("--%1 takes a share between 0 and 1").arg(name));
    return v;
}

int intOption(const QCommandLineParser &p, const QString &name, int fallback, int lo, int hi) {
    if (!p.isSet(name))
        return fallback;
    bool ok = false;
    const int v = p.value(name).toInt(&ok);
    if (!ok || v < lo || v > hi)
        die(QStringLiteral("--%1 takes a whole number from %2 to %3").arg(name).arg(lo).arg(hi));
    return v;
}

std::unique_ptr<SimLine> buildLine(const Options &o) {
    const Catalog &cat = Catalog::builtin();
    const auto *family = cat.family(o.model);
    if (!family)
        die(QStringLiteral("unknown model '%1'; known: %2")
                .arg(o.model, cat.familyNames().join(QLatin1String(", "))));
    auto line = std::make_unique<SimLine>();
    std::unique_ptr<SimDevice> first;
    if (family->isFeeder())
        first = std::make_unique<SimFeeder>(o.address >= 0 ? o.address : family->defaultAddress);
    else
        first = std::make_unique<SimStation>(family->name,
                                             o.address >= 0 ? o.address : family->defaultAddress);
    if (o.noAddr)
        first->setAddressed(false);
    first->setRobotMode(!o.robotModeOff);
    line->addDevice(std::move(first));
    if (o.feeder) {
        if (family->isFeeder())
            die(QStringLiteral(
                "--feeder adds a feeder beside a station; the model is already SFR"));
        auto feeder = std::make_unique<SimFeeder>(cat.address(QStringLiteral("feeder")));
        if (o.noAddr)
            die(QStringLiteral("two devices without addresses cannot share one line; drop "
                               "--no-addr or --feeder"));
        line->addDevice(std::move(feeder));
    }
    if (o.jointsPerMinute > 0 && family->isFeeder())
        die(QStringLiteral("--joints-per-minute needs a station; the model is SFR"));
    line->setFaults(o.faults);
    line->setBaud(o.pace);
    line->setChunkMs(o.chunkMs);
    line->setDemoActivity(o.activity);
    line->setRandomJoints(o.jointsPerMinute, o.faults.seed, o.jointShapes);
    line->setClockRunning(true);
    return line;
}

} // namespace

int main(int argc, char *argv[]) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("tipscope-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TIPSCOPE_VERSION));
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "Simulated JBC stations and SFR feeder speaking the robot protocol.\n"
        "Prints where to connect on the first line of standard output, then reads control\n"
        "commands (type 'help') from standard input."));
    p.addHelpOption();
    p.addVersionOption();
    p.addOptions({
        {QStringLiteral("model"),
         QStringLiteral("Device family: UCR ALE NAE DDE DME HDE DDR HDR SFR."),
         QStringLiteral("FAMILY"), QStringLiteral("DME")},
        {QStringLiteral("feeder"), QStringLiteral("Add an SFR feeder at address 10.")},
        {QStringLiteral("no-addr"), QStringLiteral("Start in the mode without addresses.")},
        {QStringLiteral("address"), QStringLiteral("The device's own address (default: factory)."),
         QStringLiteral("N")},
        {QStringLiteral("pty"), QStringLiteral("Serve on a new PTY (the default).")},
        {QStringLiteral("link"), QStringLiteral("Keep a symbolic link to the PTY at PATH."),
         QStringLiteral("PATH")},
        {QStringLiteral("device"),
         QStringLiteral("Serve on an existing serial device (e.g. one end of a socat pair)."),
         QStringLiteral("PATH")},
        {QStringLiteral("tcp"), QStringLiteral("Serve raw TCP on HOST:PORT (port 0 picks one)."),
         QStringLiteral("HOST:PORT")},
        {QStringLiteral("pace"),
         QStringLiteral("Pace both directions like a wire at BAUD (0: off)."),
         QStringLiteral("BAUD")},
        {QStringLiteral("chunk"),
         QStringLiteral("With --pace: hand an answer over every MS after its first byte, or "
                        "whole once it is in, as a USB adapter's latency timer or a device "
                        "server's packing does (0: a byte at a time)."),
         QStringLiteral("MS")},
        {QStringLiteral("latency"), QStringLiteral("Answer turnaround in ms."),
         QStringLiteral("MS")},
        {QStringLiteral("drop"),
         QStringLiteral("Share of requests carried out whose answer is lost (0-1)."),
         QStringLiteral("SHARE")},
        {QStringLiteral("corrupt"), QStringLiteral("Share of answers corrupted (0-1)."),
         QStringLiteral("SHARE")},
        {QStringLiteral("garbage"), QStringLiteral("Share of answers preceded by noise (0-1)."),
         QStringLiteral("SHARE")},
        {QStringLiteral("drop-requests"),
         QStringLiteral("Share of requests lost on their way: the device never sees them (0-1)."),
         QStringLiteral("SHARE")},
        {QStringLiteral("corrupt-requests"),
         QStringLiteral("Share of requests with a bit flipped on their way (0-1)."),
         QStringLiteral("SHARE")},
        {QStringLiteral("bad-data"),
         QStringLiteral("Share of answers to reads whose data field cannot be read (0-1)."),
         QStringLiteral("SHARE")},
        {QStringLiteral("nak"),
         QStringLiteral("Answer the requests --nak-for names with this NAK code."),
         QStringLiteral("CODE")},
        {QStringLiteral("nak-for"),
         QStringLiteral("What --nak applies to: all (the default), writes, or one command such as "
                        "ST1."),
         QStringLiteral("WHAT")},
        {QStringLiteral("seed"),
         QStringLiteral("Seed of the fault generator and of the random joints."),
         QStringLiteral("N")},
        {QStringLiteral("joints-per-minute"),
         QStringLiteral("Make about N joints a minute on every port of the station, drawn "
                        "from --joint-shapes; each is logged on standard error with its true "
                        "values."),
         QStringLiteral("N")},
        {QStringLiteral("joint-shapes"),
         QStringLiteral("The joints --joints-per-minute makes: demo (15-100 K, back within "
                        "0.4-3 s; the default), varied (25-90 K in 50-400 ms, back within "
                        "0.6-3.5 s, exponential or straight, overshoot, ±2 K of noise, 1.2 s "
                        "apart) or slow (10-25 K, back within 3-6 s, ±1 K of noise)."),
         QStringLiteral("NAME")},
        {QStringLiteral("robot-mode-off"),
         QStringLiteral("Start with robot mode off (stations answer NAK 00005).")},
        {QStringLiteral("activity"),
         QStringLiteral("Work like the GUI's demo: joints on port 1 every 15 s, port 2 resting "
                        "in the stand for 30 s of every 70 s, the feeder feeding 2 s every 20 s.")},
        {QStringLiteral("log"),
         QStringLiteral("Append every received and sent chunk in hex to FILE."),
         QStringLiteral("FILE")},
    });
    p.process(app);

    Options o;
    o.model = p.value(QStringLiteral("model")).toUpper();
    o.feeder = p.isSet(QStringLiteral("feeder"));
    o.activity = p.isSet(QStringLiteral("activity"));
    o.noAddr = p.isSet(QStringLiteral("no-addr"));
    o.address = intOption(p, QStringLiteral("address"), -1, 1, 99);
    o.pace = intOption(p, QStringLiteral("pace"), 0, 0, 4'000'000);
    o.chunkMs = intOption(p, QStringLiteral("chunk"), 0, 0, 1000);
    o.faults.latencyMs = intOption(p, QStringLiteral("latency"), 0, 0, 60'000);
    o.faults.dropShare = shareOption(p, QStringLiteral("drop"));
    o.faults.corruptShare = shareOption(p, QStringLiteral("corrupt"));
    o.faults.garbageShare = shareOption(p, QStringLiteral("garbage"));
    o.faults.badDataShare = shareOption(p, QStringLiteral("bad-data"));
    o.faults.requestDropShare = shareOption(p, QStringLiteral("drop-requests"));
    o.faults.requestCorruptShare = shareOption(p, QStringLiteral("corrupt-requests"));
    o.faults.nakCode = intOption(p, QStringLiteral("nak"), 0, 0, 99999);
    if (!parseNakScope(p.value(QStringLiteral("nak-for")).isEmpty()
                           ? QStringLiteral("all")
                           : p.value(QStringLiteral("nak-for")),
                       &o.faults))
        die(QStringLiteral("--nak-for takes all, writes or a command such as ST1"));
    o.faults.seed = quint32(intOption(p, QStringLiteral("seed"), 1, 0, 1 << 30));
    o.robotModeOff = p.isSet(QStringLiteral("robot-mode-off"));
    o.jointsPerMinute = intOption(p, QStringLiteral("joints-per-minute"), 0, 0, 60);
    if (p.isSet(QStringLiteral("joint-shapes"))) {
        const QString name = p.value(QStringLiteral("joint-shapes"));
        const auto shapes = JointShapeSet::named(name);
        if (!shapes)
            die(QStringLiteral("--joint-shapes takes %1, not %2")
                    .arg(JointShapeSet::names().join(QStringLiteral(", ")), name));
        o.jointShapes = *shapes;
    }
    auto line = buildLine(o);
    // The ground truth of every joint, one line each, for whoever measures them.
    QObject::connect(line.get(), &SimLine::jointMade, &app, [](const SimJoint &j) {
        QTextStream(stderr) << "tipscope-sim: joint port=" << j.port << " start_ms=" << j.startMs
                            << " depth_k=" << j.depthK << " recovery_ms=" << j.recoveryMs
                            << " drop_ms=" << qRound(j.dropMs)
                            << " form=" << recoveryFormName(j.form)
                            << " overshoot_k=" << QString::number(j.overshootK, 'f', 1) << Qt::endl;
    });
    QObject::connect(line.get(), &SimLine::jointEnded, &app, [](const SimJoint &j) {
        QTextStream(stderr) << "tipscope-sim: joint-end port=" << j.port
                            << " start_ms=" << j.startMs << " reads=" << j.reads
                            << " read_depth_k=" << QString::number(j.readDepthK, 'f', 2)
                            << Qt::endl;
    });

    QFile log;
    if (p.isSet(QStringLiteral("log"))) {
        log.setFileName(p.value(QStringLiteral("log")));
        if (!log.open(QIODevice::Append | QIODevice::Text | QIODevice::Unbuffered))
            die(QStringLiteral("cannot write %1: %2").arg(log.fileName(), log.errorString()));
        QObject::connect(line.get(), &SimLine::transmit, &app,
                         [&log](const QByteArray &b) { log.write("TX " + b.toHex() + '\n'); });
    }

    std::unique_ptr<PtyEndpoint> pty;
    std::unique_ptr<SerialDeviceEndpoint> serial;
    std::unique_ptr<TcpEndpoint> tcp;
    QString where;
    if (p.isSet(QStringLiteral("tcp"))) {
        tcp = std::make_unique<TcpEndpoint>(*line);
        if (const auto listening = tcp->listen(p.value(QStringLiteral("tcp"))); !listening)
            die(listening.error());
        const QString hp = p.value(QStringLiteral("tcp"));
        where = hp.left(hp.lastIndexOf(QLatin1Char(':')) + 1) + QString::number(tcp->port());
    } else if (p.isSet(QStringLiteral("device"))) {
        serial = std::make_unique<SerialDeviceEndpoint>(*line, p.value(QStringLiteral("device")));
        if (const auto opened = serial->open(); !opened)
            die(opened.error());
        where = p.value(QStringLiteral("device"));
    } else {
        pty = std::make_unique<PtyEndpoint>(*line, p.value(QStringLiteral("link")));
        if (const auto plugged = pty->plug(); !plugged)
            die(plugged.error());
        where = pty->slavePath();
    }
    // Log what arrives after the endpoint exists, so the log sees exactly the wire.
    if (log.isOpen())
        QObject::connect(line.get(), &SimLine::requestReceived, &app,
                         [&log](const tipscope::protocol::Frame &f) {
                             log.write("RX " + f.encode().toHex() + '\n');
                         });
    out() << where << Qt::endl;
    QTextStream(stderr) << "tipscope-sim: " << o.model << (o.feeder ? " + SFR" : "")
                        << (o.noAddr ? " without addresses" : " with addresses") << " on " << where
                        << Qt::endl;

    // The endpoint's own commands, beside SimControl's; help lists both.
    struct EndpointCommand {
        QString verb;
        std::function<QString()> run;
    };
    QList<EndpointCommand> endpointCommands;
    if (pty) {
        endpointCommands.append({QStringLiteral("unplug"), [&] {
                                     pty->unplug();
                                     return QStringLiteral("ok");
                                 }});
        endpointCommands.append({QStringLiteral("plug"), [&] {
                                     const auto plugged = pty->plug();
                                     return plugged ? pty->slavePath()
                                                    : QStringLiteral("error: ") + plugged.error();
                                 }});
    }
    const auto reply = [&](const QString &c) {
        for (const EndpointCommand &e : endpointCommands)
            if (c == e.verb)
                return e.run();
        if (c.section(QLatin1Char(' '), 0, 0) != QLatin1String("help"))
            return executeSimCommand(*line, c);
        QStringList verbs;
        for (const EndpointCommand &e : endpointCommands)
            verbs.append(e.verb);
        return simCommandUsage(verbs);
    };

    const auto run = [&](const QByteArray &cmd) {
        const QString c = QString::fromLocal8Bit(cmd).trimmed();
        if (!c.isEmpty())
            out() << reply(c) << Qt::endl;
    };
    // Whole lines only: a read ends anywhere, and the part of a long line after it must not run
    // as a command of its own. A line beyond the bound is dropped to its end, and said.
    QByteArray pending;
    bool overlong = false;
    QSocketNotifier input(STDIN_FILENO, QSocketNotifier::Read);
    QObject::connect(&input, &QSocketNotifier::activated, &app, [&] {
        char buf[4096];
        const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
        if (n <= 0) {
            input.setEnabled(false); // end of input: keep serving until killed
            if (!overlong)
                run(pending);
            return;
        }
        pending.append(buf, qsizetype(n));
        for (qsizetype end = pending.indexOf('\n'); end >= 0; end = pending.indexOf('\n')) {
            const QByteArray cmd = pending.left(end);
            pending.remove(0, end + 1);
            if (std::exchange(overlong, false) || cmd.size() > kMaxCommandBytes)
                out() << QStringLiteral("error: a command line longer than %1 bytes is ignored")
                             .arg(kMaxCommandBytes)
                      << Qt::endl;
            else
                run(cmd);
        }
        if (pending.size() > kMaxCommandBytes) {
            overlong = true;
            pending.clear();
        }
    });
    return app.exec();
}
