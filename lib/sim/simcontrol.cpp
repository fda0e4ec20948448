#include "simcontrol.h"

#include "simline.h"

#include <QStringList>
#include <algorithm>

namespace tipscope::sim {

namespace {

enum class Handler { Station, Line, Feeder, Joint, Get, Stats, Help };

struct CommandEntry {
    const char *verb;
    const char *arguments;
    Handler handler;
};

// Every command executeSimCommand() accepts: the parser dispatches through this table and help
// lists it, so a command cannot be accepted without being listed.
constexpr CommandEntry kCommands[] = {
    {"port-error", "PORT CODE", Handler::Station},
    {"station-error", "CODE", Handler::Station},
    {"tool", "PORT TOOL", Handler::Station},
    {"alarm", "PORT FLAGS", Handler::Station},
    {"status", "PORT STATUS", Handler::Station},
    {"robot-mode", "on|off", Handler::Station},
    {"fuse", "on|off", Handler::Station},
    {"feeder-error", "CODE", Handler::Feeder},
    {"joint", "PORT DEPTH RECOVERY_MS", Handler::Joint},
    {"wear", "PORT SHARE", Handler::Joint},
    {"drop", "SHARE", Handler::Line},
    {"corrupt", "SHARE", Handler::Line},
    {"garbage", "SHARE", Handler::Line},
    {"bad-data", "SHARE", Handler::Line},
    {"drop-requests", "SHARE", Handler::Line},
    {"corrupt-requests", "SHARE", Handler::Line},
    {"nak", "CODE [all|writes|COMMAND]", Handler::Line},
    {"latency", "MS", Handler::Line},
    {"pace", "BAUD", Handler::Line},
    {"get", "[CODE...]", Handler::Get},
    {"stats", "", Handler::Stats},
    {"help", "", Handler::Help},
};

const CommandEntry *findCommand(const QString &verb) {
    for (const CommandEntry &e : kCommands)
        if (verb == QLatin1String(e.verb))
            return &e;
    return nullptr;
}

QString usage() {
    return simCommandUsage({});
}

QString stats(const SimLine &line) {
    const SimLineStats &s = line.stats();
    return QStringLiteral("requests %1 writes %2 answers %3 dropped %4 corrupted %5 garbled %6 "
                          "bad-requests %7 bytes-in %8 bytes-out %9 bad-data %10 overrun %11 "
                          "unsent %12 lost-requests %13 garbled-requests %14")
        .arg(s.requests)
        .arg(s.writeRequests)
        .arg(s.answers)
        .arg(s.dropped)
        .arg(s.corrupted)
        .arg(s.garbled)
        .arg(s.badRequests)
        .arg(s.bytesReceived)
        .arg(s.bytesSent)
        .arg(s.badData)
        .arg(s.overrunBytes)
        .arg(s.unsentBytes)
        .arg(s.requestsLost)
        .arg(s.requestsGarbled);
}

// "ST1=350 A11=0": the stored settings of the first device holding each code, all of the first
// device's without codes. The device's memory itself, not what it answers on the wire.
QString storedSettings(const SimLine &line, const QStringList &codes) {
    const QList<SimDevice *> devices = line.devices();
    if (devices.isEmpty())
        return QStringLiteral("error: no device on this line");
    QStringList out;
    const QList<QByteArray> wanted = [&] {
        QList<QByteArray> c;
        for (const QString &code : codes)
            c.append(code.toUpper().toLatin1());
        return c.isEmpty() ? devices.first()->settings().keys() : c;
    }();
    for (const QByteArray &code : wanted) {
        std::optional<qint64> value;
        for (const SimDevice *d : devices)
            if (!value)
                value = d->setting(code);
        if (!value)
            return QStringLiteral("error: no device holds a setting %1")
                .arg(QString::fromLatin1(code));
        out.append(QStringLiteral("%1=%2").arg(QString::fromLatin1(code)).arg(*value));
    }
    return out.join(QLatin1Char(' '));
}

struct Args {
    QStringList words;
    bool ok = true;
    int integer(int i) {
        bool good = false;
        const int v = words.value(i).toInt(&good);
        ok = ok && good;
        return v;
    }
    double share(int i) {
        bool good = false;
        const double v = words.value(i).toDouble(&good);
        ok = ok && good && v >= 0 && v <= 1;
        return v;
    }
    bool onOff(int i) {
        const QString w = words.value(i);
        ok = ok && (w == QLatin1String("on") || w == QLatin1String("off"));
        return w == QLatin1String("on");
    }
};

QString applyStationCommand(SimLine &line, const QString &verb, Args &a) {
    SimStation *st = line.station();
    if (!st)
        return QStringLiteral("error: there is no station on this line");
    const bool needsPort = verb != QLatin1String("station-error") &&
                           verb != QLatin1String("robot-mode") && verb != QLatin1String("fuse");
    const int port = needsPort ? a.integer(1) : 0;
    if (needsPort && (port < 1 || port > st->portCount()))
        return QStringLiteral("error: port must be 1 to %1").arg(st->portCount());
    if (verb == QLatin1String("port-error")) {
        const int code = a.integer(2);
        if (a.ok)
            st->setPortError(port, code);
    } else if (verb == QLatin1String("tool")) {
        const int tool = a.integer(2);
        if (a.ok)
            st->setTool(port, tool);
    } else if (verb == QLatin1String("alarm")) {
        const int flags = a.integer(2);
        if (a.ok)
            st->latchAlarm(port, flags);
    } else if (verb == QLatin1String("status")) {
        const int status = a.integer(2);
        a.ok = a.ok && status >= 0 && status <= 3;
        if (a.ok)
            st->setStatus(port, status);
    } else if (verb == QLatin1String("station-error")) {
        const int code = a.integer(1);
        if (a.ok)
            st->setStationError(code);
    } else if (verb == QLatin1String("robot-mode")) {
        const bool on = a.onOff(1);
        if (a.ok)
            st->setRobotMode(on);
    } else if (verb == QLatin1String("fuse")) {
        const bool on = a.onOff(1);
        if (a.ok)
            st->setFuse(on);
    }
    return a.ok ? QStringLiteral("ok") : QStringLiteral("error: bad arguments; ") + usage();
}

QString applyLineCommand(SimLine &line, const QString &verb, Args &a) {
    SimFaults f = line.faults();
    if (verb == QLatin1String("drop"))
        f.dropShare = a.share(1);
    else if (verb == QLatin1String("corrupt"))
        f.corruptShare = a.share(1);
    else if (verb == QLatin1String("garbage"))
        f.garbageShare = a.share(1);
    else if (verb == QLatin1String("bad-data"))
        f.badDataShare = a.share(1);
    else if (verb == QLatin1String("drop-requests"))
        f.requestDropShare = a.share(1);
    else if (verb == QLatin1String("corrupt-requests"))
        f.requestCorruptShare = a.share(1);
    else if (verb == QLatin1String("nak")) {
        f.nakCode = a.integer(1);
        a.ok = a.ok && f.nakCode >= 0 && f.nakCode <= 99999 && a.words.size() <= 3 &&
               parseNakScope(a.words.value(2, QStringLiteral("all")), &f);
    } else if (verb == QLatin1String("latency"))
        f.latencyMs = a.integer(1);
    else if (verb == QLatin1String("pace")) {
        const int baud = a.integer(1);
        if (a.ok && baud >= 0)
            line.setBaud(baud);
        return a.ok && baud >= 0 ? QStringLiteral("ok") : QStringLiteral("error: bad baud rate");
    }
    if (!a.ok)
        return QStringLiteral("error: bad arguments; ") + usage();
    line.setFaults(f);
    return QStringLiteral("ok");
}

QString applyFeederCommand(SimLine &line, Args &a) {
    SimFeeder *f = line.feeder();
    const int code = a.integer(1);
    if (!f || !a.ok)
        return QStringLiteral("error: no feeder on this line, or a bad code");
    f->setError(code);
    return QStringLiteral("ok");
}

// "joint PORT DEPTH RECOVERY_MS" and "wear PORT SHARE": the station's joints (JointShape).
QString applyJointCommand(SimLine &line, const QString &verb, Args &a) {
    SimStation *st = line.station();
    if (!st)
        return QStringLiteral("error: there is no station on this line");
    const int port = a.integer(1);
    if (!a.ok || port < 1 || port > st->portCount())
        return QStringLiteral("error: port must be 1 to %1").arg(st->portCount());
    if (verb == QLatin1String("wear")) {
        const double share = a.share(2);
        if (!a.ok || a.words.size() != 3)
            return QStringLiteral("error: wear takes PORT SHARE, a share from 0 to 1 (0.3: "
                                  "recoveries 30 % slower)");
        st->setWear(port, share);
        return QStringLiteral("ok");
    }
    const int depth = a.integer(2);
    const int recovery = a.integer(3);
    if (!a.ok || a.words.size() != 4)
        return QStringLiteral("error: joint takes PORT DEPTH RECOVERY_MS, whole numbers (K, ms)");
    if (const QString wrong = JointShape::checkRequest(depth, recovery); !wrong.isEmpty())
        return QStringLiteral("error: ") + wrong;
    if (!line.startJoint(port, depth, recovery))
        return QStringLiteral("error: port %1 cannot make a joint now: it is not at work at its "
                              "temperature, or a joint is in progress")
            .arg(port);
    return QStringLiteral("ok");
}

} // namespace

bool parseNakScope(const QString &text, SimFaults *faults) {
    if (text == QLatin1String("all") || text == QLatin1String("writes")) {
        faults->nakFor = text == QLatin1String("all") ? NakScope::All : NakScope::Writes;
        faults->nakCommand.clear();
        return true;
    }
    const QByteArray code = text.toUpper().toLatin1();
    const bool isCode = code.size() == 3 && std::all_of(code.begin(), code.end(), [](char c) {
                            return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
                        });
    if (!isCode)
        return false;
    faults->nakFor = NakScope::Command;
    faults->nakCommand = code;
    return true;
}

QString simCommandUsage(const QStringList &more) {
    QStringList forms;
    for (const CommandEntry &e : kCommands)
        forms.append(
            QString::fromLatin1(e.verb) +
            (*e.arguments ? QLatin1Char(' ') + QString::fromLatin1(e.arguments) : QString()));
    return QStringLiteral("commands: ") + (forms + more).join(QLatin1String(" | "));
}

QString executeSimCommand(SimLine &line, const QString &command) {
    Args a{command.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts)};
    const QString verb = a.words.value(0);
    const CommandEntry *entry =
        verb.isEmpty() ? findCommand(QStringLiteral("help")) : findCommand(verb);
    if (!entry)
        return QStringLiteral("error: unknown command '%1'; ").arg(verb) + usage();
    switch (entry->handler) {
    case Handler::Help:
        return usage();
    case Handler::Stats:
        return stats(line);
    case Handler::Get:
        return storedSettings(line, a.words.mid(1));
    case Handler::Station:
        return applyStationCommand(line, verb, a);
    case Handler::Line:
        return applyLineCommand(line, verb, a);
    case Handler::Feeder:
        return applyFeederCommand(line, a);
    case Handler::Joint:
        return applyJointCommand(line, verb, a);
    }
    return usage();
}

} // namespace tipscope::sim
