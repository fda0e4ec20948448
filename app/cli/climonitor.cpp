// tipscope-cli monitor: tip temperature, setpoint, power and status of every port, polled in
// cycles through the live-poll priority. A lost line is reported and the line reconnects by
// itself; the monitor resumes when it is back.
#include "clicommands.h"

#include "protocol/elide.h"
#include "protocol/valuecodec.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QTimer>
#include <cmath>

namespace tipscope::cli {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(CliMonitor)
};

struct PortReading {
    QString tip, setpoint, power, status;
    bool ok = false;
};

const QList<Role> kLiveRoles = {Role::TipTemperature, Role::Setpoint, Role::Power, Role::Status};

PortReading readPort(CliSession &s, const DeviceInfo &d, int port, int *worst) {
    PortReading r;
    QStringList fields;
    for (const Role role : kLiveRoles) {
        const auto cmd = Catalog::builtin().resolve(d.family, role, port, Direction::Read);
        if (!cmd)
            return r;
        Reply *reply = s.ask(Request::read(d.address, *cmd, Priority::LivePoll));
        reply->deleteLater();
        if (!reply->ok()) {
            *worst = qMax(*worst, CliSession::exitCodeFor(*reply));
            return r;
        }
        const auto value = decodeAnswer(*cmd, reply->answer().data);
        if (!value)
            return r;
        if (role == Role::Power)
            fields.append(QString::number(value->number / 10.0, 'f', 1));
        else
            fields.append(describeValue(*cmd, *value, Wording::Catalog)); // data: English
    }
    r = {fields[0], fields[1], fields[2], fields[3], true};
    return r;
}

} // namespace

int runMonitor(CliSession &s) {
    bool ok = true;
    const int intervalMs =
        s.options().values.value(QStringLiteral("interval"), QStringLiteral("1000")).toInt(&ok);
    if (!ok || intervalMs < 0) {
        s.err()
            << Tr::tr("tipscope-cli: --interval takes milliseconds (0: as fast as the line allows)")
            << Qt::endl;
        return kUsage;
    }
    const double durationS =
        s.options().values.value(QStringLiteral("duration"), QStringLiteral("0")).toDouble(&ok);
    if (!ok || !std::isfinite(durationS) || durationS < 0 || durationS > 1e9) {
        s.err() << Tr::tr("tipscope-cli: --duration takes seconds") << Qt::endl;
        return kUsage;
    }
    if (const int rc = s.resolveDevices(); rc != kOk)
        return rc;
    const DeviceInfo *station = s.firstStation();
    if (!station) {
        s.err() << Tr::tr("tipscope-cli: monitor needs a station; none was found") << Qt::endl;
        return kUsage;
    }
    const DeviceInfo d = *station;
    const int ports = Catalog::builtin().family(d.family)->ports;
    QFile csv;
    if (s.options().values.contains(QStringLiteral("csv"))) {
        csv.setFileName(s.options().values.value(QStringLiteral("csv")));
        if (!csv.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
            s.err() << Tr::tr("tipscope-cli: cannot write %1: %2")
                           .arg(elidedPath(csv.fileName()), csv.errorString())
                    << Qt::endl;
            return kUsage;
        }
        csv.write(QStringLiteral("# %1\ntimestamp,port,tip_c,setpoint_c,power_pct,status\n")
                      .arg(d.summary())
                      .toUtf8());
    }
    // The line retries every second while it is down, and each attempt changes its state: the
    // loss is said once, and so is the return.
    QObject watching;
    bool lost = false;
    QObject::connect(&s.line(), &Line::stateChanged, &watching, [&s, &lost](Line::State state) {
        if (state == Line::State::Retrying && !lost)
            s.err() << "# " << s.line().stateText() << Qt::endl;
        else if (state == Line::State::Open && lost)
            s.err() << "# " << Tr::tr("reconnected to %1").arg(s.line().transport().description())
                    << Qt::endl;
        if (state == Line::State::Retrying || state == Line::State::Open)
            lost = state == Line::State::Retrying;
    });
    QElapsedTimer clock;
    clock.start();
    int lastCycle = kOk;
    while (durationS == 0 || clock.elapsed() < qint64(durationS * 1000)) {
        const qint64 cycleStart = clock.elapsed();
        int worst = kOk;
        QStringList parts;
        const QString stamp = QDateTime::currentDateTime().toString(Qt::ISODateWithMs);
        for (int p = 1; p <= ports; ++p) {
            const PortReading r = readPort(s, d, p, &worst);
            if (!r.ok) {
                parts.append(Tr::tr("P%1 --").arg(p));
                continue;
            }
            parts.append(QStringLiteral("P%1 %2/%3 °C %4% %5")
                             .arg(p)
                             .arg(r.tip, r.setpoint, r.power, r.status));
            if (csv.isOpen())
                csv.write(QStringLiteral("%1,%2,%3,%4,%5,\"%6\"\n")
                              .arg(stamp)
                              .arg(p)
                              .arg(r.tip, r.setpoint, r.power, r.status)
                              .toUtf8());
        }
        if (csv.isOpen())
            csv.flush();
        s.out() << stamp << "  " << parts.join(QLatin1String(" | ")) << Qt::endl;
        lastCycle = worst;
        const qint64 wait = intervalMs - (clock.elapsed() - cycleStart);
        // A lost line fails requests at once: wait a beat instead of spinning through cycles.
        const qint64 pause = worst != kOk ? qMax<qint64>(wait, 200) : wait;
        if (pause > 0) {
            QEventLoop loop;
            QTimer::singleShot(int(pause), &loop, &QEventLoop::quit);
            loop.exec();
        }
    }
    return lastCycle;
}

} // namespace tipscope::cli
