// tipscope-cli monitor: tip temperature, setpoint, power and status of every port, polled in
// cycles through the live-poll priority. A lost line is reported and the line reconnects by
// itself; the monitor resumes when it is back. Each port's readings also go through the joint
// detector the GUI uses, judged by the shared joint limits (and --limit); every joint is a line
// of its own and is kept in the journal with the work context in force.
#include "clicommands.h"

#include "climonitorcsv.h"
#include "climonitorjoints.h"

#include "model/devicemodel.h"
#include "model/joints/jointlimitsfile.h"
#include "model/portmodel.h"

#include "protocol/elide.h"
#include "protocol/valuecodec.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <cmath>

namespace tipscope::cli {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {

struct CliMonitorTr {
    Q_DECLARE_TR_FUNCTIONS(CliMonitor)
};

struct PortReading {
    QString tip, setpoint, power, status;
    bool ok = false;
    model::PortReading joint; // the same, for the joint detector
};

const QList<Role> kLiveRoles = {Role::TipTemperature, Role::Setpoint, Role::Power, Role::Status};
constexpr int kToolEveryCycles = 10; // the tool rarely changes: read it now and then

PortReading readPort(CliSession &s, const DeviceInfo &d, int port, int *worst) {
    PortReading r;
    QStringList fields;
    QList<qint64> numbers;
    r.joint.timeMs = QDateTime::currentMSecsSinceEpoch();
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
        numbers.append(value->number);
        if (role == Role::Power)
            fields.append(QString::number(value->number / 10.0, 'f', 1));
        else
            fields.append(describeValue(*cmd, *value, Wording::Catalog)); // data: English
    }
    r.tip = fields[0];
    r.setpoint = fields[1];
    r.power = fields[2];
    r.status = fields[3];
    r.ok = true;
    r.joint.tip = int(numbers[0]);
    r.joint.setpoint = int(numbers[1]);
    r.joint.powerPct = double(numbers[2]) / 10;
    r.joint.working =
        model::PortStatus::fromNumber(numbers[3]).mode == model::PortStatus::Mode::Working;
    return r;
}

QString readTool(CliSession &s, const DeviceInfo &d, int port) {
    const auto cmd =
        Catalog::builtin().resolve(d.family, Role::ConnectedTool, port, Direction::Read);
    if (!cmd)
        return {};
    Reply *reply = s.ask(Request::read(d.address, *cmd, Priority::LivePoll));
    reply->deleteLater();
    const auto value = reply->ok() ? decodeAnswer(*cmd, reply->answer().data) : std::nullopt;
    return value
               ? model::toolName(Catalog::builtin(), d.family, int(value->number), Wording::Catalog)
               : QString();
}

// The line's limits (a workspace's) or the shared ones, with --limit's rule on top.
protocol::Outcome<model::JointLimitRules> limitsOf(const CliOptions &o) {
    auto rules = o.lineLimits ? protocol::Outcome<model::JointLimitRules>(*o.lineLimits)
                              : model::loadJointLimits(model::defaultJointLimitsPath());
    if (!rules || !o.values.contains(QStringLiteral("limit")))
        return rules;
    const auto rule = model::JointLimitRules::parseRule(o.values.value(QStringLiteral("limit")));
    if (!rule)
        return protocol::failure(QStringLiteral("--limit: %1").arg(rule.error()));
    model::JointLimitRules out = rules.value();
    out.add(rule.value());
    return out;
}

} // namespace

int runMonitor(CliSession &s) {
    bool ok = true;
    const int intervalMs =
        s.options().values.value(QStringLiteral("interval"), QStringLiteral("1000")).toInt(&ok);
    if (!ok || intervalMs < 0) {
        s.err()
            << CliMonitorTr::tr(
                   "tipscope-cli: --interval takes milliseconds (0: as fast as the line allows)")
            << Qt::endl;
        return kUsage;
    }
    const double durationS =
        s.options().values.value(QStringLiteral("duration"), QStringLiteral("0")).toDouble(&ok);
    if (!ok || !std::isfinite(durationS) || durationS < 0 || durationS > 1e9) {
        s.err() << CliMonitorTr::tr("tipscope-cli: --duration takes seconds") << Qt::endl;
        return kUsage;
    }
    const auto limits = limitsOf(s.options());
    if (!limits) {
        s.err() << "tipscope-cli: " << limits.error() << Qt::endl;
        return kRefused;
    }
    if (const int rc = s.resolveDevices(); rc != kOk)
        return rc;
    const DeviceInfo *station = s.firstStation();
    if (!station) {
        s.err() << CliMonitorTr::tr("tipscope-cli: monitor needs a station; none was found")
                << Qt::endl;
        return kUsage;
    }
    const DeviceInfo d = *station;
    const int ports = Catalog::builtin().family(d.family)->ports;
    std::shared_ptr<MonitorCsv> csv = s.options().sharedCsv;
    if (!csv && s.options().values.contains(QStringLiteral("csv"))) {
        auto created = MonitorCsv::create(s.options().values.value(QStringLiteral("csv")), false);
        if (!created) {
            s.err() << created.error() << Qt::endl;
            return kUsage;
        }
        csv = created.value();
    }
    if (csv)
        csv->describe(s.options().lineName, d.summary());
    // The line retries every second while it is down, and each attempt changes its state: the
    // loss is said once, and so is the return.
    QObject watching;
    bool lost = false;
    QObject::connect(&s.line(), &Line::stateChanged, &watching, [&s, &lost](Line::State state) {
        if (state == Line::State::Retrying && !lost)
            s.err() << "# " << s.line().stateText() << Qt::endl;
        else if (state == Line::State::Open && lost)
            s.err() << "# "
                    << CliMonitorTr::tr("reconnected to %1").arg(s.line().transport().description())
                    << Qt::endl;
        if (state == Line::State::Retrying || state == Line::State::Open)
            lost = state == Line::State::Retrying;
    });
    MonitorJoints joints(s, d, ports, limits.value());
    QStringList tools(ports);
    QElapsedTimer clock;
    clock.start();
    int lastCycle = kOk;
    for (int cycle = 0; durationS == 0 || clock.elapsed() < qint64(durationS * 1000); ++cycle) {
        const qint64 cycleStart = clock.elapsed();
        int worst = kOk;
        QStringList parts;
        const QString stamp = QDateTime::currentDateTime().toString(Qt::ISODateWithMs);
        for (int p = 1; p <= ports; ++p) {
            if (cycle % kToolEveryCycles == 0)
                tools[p - 1] = readTool(s, d, p);
            PortReading r = readPort(s, d, p, &worst);
            if (!r.ok) {
                joints.gap(p, r.joint.timeMs);
                parts.append(CliMonitorTr::tr("P%1 --").arg(p));
                continue;
            }
            r.joint.tool = tools.at(p - 1);
            joints.add(p, r.joint);
            parts.append(QStringLiteral("P%1 %2/%3 °C %4% %5")
                             .arg(p)
                             .arg(r.tip, r.setpoint, r.power, r.status));
            if (csv)
                csv->write(
                    s.options().lineName, stamp, p,
                    QStringLiteral("%1,%2,%3,\"%4\"").arg(r.tip, r.setpoint, r.power, r.status));
        }
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
    if (!joints.finish() && lastCycle == kOk)
        lastCycle = kTransport;
    return lastCycle;
}

} // namespace tipscope::cli
