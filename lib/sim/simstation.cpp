#include "simstation.h"

#include <QtMath>
#include <utility>

namespace tipscope::sim {

using namespace tipscope::protocol;

namespace {
constexpr double kHeatRatePerS = 120.0; // °C/s at full power
constexpr double kLossPerS = 0.15;      // fraction of (tip - room) lost per second
constexpr double kGain = 40.0;          // per mille per °C of error
constexpr int kMaxStepMs = 50;
constexpr int kNoToolError = 4;
constexpr qint64 kDisabledDelay = 99999;

bool heaterBlocked(int error) {
    return error == 1 || error == 2 || error == 3 || error == 4 || error == 5 || error == 8;
}
} // namespace

SimStation::SimStation(const QString &family, int address)
    : SimDevice(family, address) {
    setModelName(family == QLatin1String("DDR")   ? QStringLiteral("DDR")
                 : family == QLatin1String("UCR") ? QStringLiteral("UCR245")
                                                  : family + QStringLiteral("-2C"));
    setSoftwareVersion(QStringLiteral("9996780"));
    const FamilyInfo &f = this->family();
    // The family decides once whether alarms wait a delay; each step of the physics asked.
    m_hasAlarmDelays = m_catalog.resolve(f.name, "HD1", Direction::Read).has_value();
    for (int i = 0; i < f.ports; ++i) {
        SimPort p;
        p.tool = f.tools.value(i % f.tools.size(), 0);
        // Counters start at plausible values so that a fresh simulator does not read all zeros.
        p.pluggedS = 3600.0 * (1200 + 37 * i);
        p.workS = 3600.0 * (800 + 23 * i);
        p.sleepS = 3600.0 * (150 + 11 * i);
        p.hibernationS = 3600.0 * (90 + 5 * i);
        p.noToolS = 3600.0 * (40 + 3 * i);
        p.sleepCycles = 2000 + 100 * i;
        p.desolderCycles = p.tool == 5 || p.tool == 6 ? 5000 + 10 * i : 0;
        m_ports.append(p);
    }
    restoreFactorySettings();
}

void SimStation::restoreFactorySettings() {
    SimDevice::restoreFactorySettings();
    m_savedSelected.clear();
    for (int n = 1; n <= portCount(); ++n)
        m_savedSelected.insert("ST" + QByteArray::number(n), settingOr("ST1", 350));
}

void SimStation::setTool(int port, int tool) {
    SimPort &p = m_ports[port - 1];
    p.tool = tool;
    if (tool == 0)
        p.error = kNoToolError;
    else if (p.error == kNoToolError)
        p.error = 0;
}

void SimStation::setPortError(int port, int code) {
    m_ports[port - 1].error = code;
}

void SimStation::setStatus(int port, int status) {
    SimPort &p = m_ports[port - 1];
    p.status = status;
    p.secondsInStatus = 0;
}

bool SimStation::canMakeJoint(int port) const {
    const SimPort &p = m_ports.at(port - 1);
    // At work and at its temperature: a joint is measured from a settled tip.
    return p.tool != 0 && p.status == 0 && !p.cooling && !heaterBlocked(p.error) && !p.joint &&
           qAbs(p.tip - targetFor(p, port)) <= JointShape::kBandK;
}

std::optional<SimJoint> SimStation::startJoint(int port, int depthK, qint64 recoveryMs) {
    return startJoint(port, JointSpec{depthK, recoveryMs});
}

std::optional<SimJoint> SimStation::startJoint(int port, JointSpec spec) {
    if (!canMakeJoint(port))
        return std::nullopt;
    SimPort &p = m_ports[port - 1];
    spec.recoveryMs = qRound64(double(spec.recoveryMs) * (1 + p.wear));
    const JointShape shape(spec);
    const SimJoint made = shape.made(port, m_nowMs);
    p.joint = ActiveJoint{shape, 0, made};
    m_madeJoints.append(made);
    return made;
}

void SimStation::setReadingNoise(double amplitudeK, bool duringJoints) {
    m_noiseK = qBound(0.0, amplitudeK, 10.0);
    m_noiseDuringJoints = duringJoints;
}

QList<SimJoint> SimStation::takeMadeJoints() {
    return std::exchange(m_madeJoints, {});
}

QList<SimJoint> SimStation::takeEndedJoints() {
    return std::exchange(m_endedJoints, {});
}

QByteArray SimStation::toolCode(char letter, int port, int tool) const {
    return QByteArray(1, letter) + QByteArray::number(port) + QByteArray::number(tool);
}

double SimStation::targetFor(const SimPort &p, int n) const {
    if (p.tool == 0 || p.cooling || heaterBlocked(p.error) || p.status == 3)
        return kAmbient;
    if (p.status == 2)
        return double(settingOr(toolCode('S', n, p.tool), 150));
    const qint64 selected = settingOr("ST" + QByteArray::number(n), 350);
    return double(selected + settingOr(toolCode('A', n, p.tool), 0));
}

void SimStation::advance(int ms) {
    while (ms > 0) {
        const int chunk = qMin(ms, kMaxStepMs);
        for (int i = 0; i < m_ports.size(); ++i)
            step(m_ports[i], i + 1, chunk / 1000.0);
        m_noisePhase += chunk / 1000.0;
        m_nowMs += chunk;
        ms -= chunk;
    }
}

void SimStation::step(SimPort &p, int n, double dt) {
    const double target = targetFor(p, n);
    const qint64 limit =
        family().name == QLatin1String("DDR") || family().name == QLatin1String("HDR")
            ? settingOr("PLM", 1000)
            : 1000;
    double demand = 0;
    if (target > kAmbient) {
        const double hold = (target - kAmbient) * kLossPerS / kHeatRatePerS * 1000.0;
        demand = hold + (target - p.tip) * kGain;
    }
    p.power = int(qBound(0.0, demand, double(limit)));
    p.tip += dt * (p.power / 1000.0 * kHeatRatePerS - (p.tip - kAmbient) * kLossPerS);
    stepJoint(p, target, dt);
    p.secondsInStatus += dt;
    if (p.tool == 0) {
        p.noToolS += dt;
    } else {
        p.pluggedS += dt;
        (p.status == 0   ? p.workS
         : p.status == 2 ? p.sleepS
         : p.status == 3 ? p.hibernationS
                         : p.workS) += dt;
    }
    if (p.motor != 0) {
        const double moved = dt * double(settingOr("SPD", 100));
        p.dispensedDmm += moved;
        if (settingOr("MOD", 0) == 1) {
            p.dispenseLeftDmm -= moved;
            if (p.dispenseLeftDmm <= 0)
                p.motor = 0;
        }
    }
    updateSleep(p, n, dt);
    updateAlarms(p, n, dt);
}

// The joint holds the tip on its shape below the target; the controller, seeing the tip low,
// answers with power on the next step. A port that leaves work ends its joint.
void SimStation::stepJoint(SimPort &p, double target, double dt) {
    if (!p.joint)
        return;
    p.joint->elapsedMs += dt * 1000;
    if (p.tool == 0 || p.status != 0 || p.cooling || heaterBlocked(p.error) ||
        p.joint->shape.isOver(p.joint->elapsedMs)) {
        m_endedJoints.append(p.joint->made);
        p.joint.reset();
        return;
    }
    p.tip = qMax(kAmbient, target - p.joint->shape.belowTargetK(p.joint->elapsedMs));
}

void SimStation::updateSleep(SimPort &p, int n, double) {
    if (p.tool == 0)
        return;
    if (p.status == 1) {
        const qint64 delayMin = settingOr(toolCode('D', n, p.tool), 0);
        if (delayMin != kDisabledDelay && p.secondsInStatus >= delayMin * 60.0) {
            p.status = 2;
            p.secondsInStatus = 0;
            ++p.sleepCycles;
        }
    } else if (p.status == 2) {
        const qint64 delayMin = settingOr(toolCode('H', n, p.tool), 10);
        if (delayMin != kDisabledDelay && p.secondsInStatus >= delayMin * 60.0) {
            p.status = 3;
            p.secondsInStatus = 0;
        }
    }
}

void SimStation::updateAlarms(SimPort &p, int n, double dt) {
    const QByteArray port = QByteArray::number(n);
    auto delayOf = [&](const QByteArray &code) -> double {
        if (!m_hasAlarmDelays)
            return 0;
        const qint64 v = settingOr(code + port, kDisabledDelay);
        return v == kDisabledDelay ? -1 : v / 100.0;
    };
    const bool watching = p.status == 0 && p.tool != 0;
    p.highFor = watching && p.tip > settingOr("HA" + port, 9999) ? p.highFor + dt : 0;
    p.lowFor = watching && p.tip < settingOr("LA" + port, -9999) ? p.lowFor + dt : 0;
    const double hd = delayOf("HD");
    const double ld = delayOf("LD");
    if (hd >= 0 && p.highFor > hd)
        p.alarmFlags |= 1;
    if (ld >= 0 && p.lowFor > ld)
        p.alarmFlags |= 10;
}

std::optional<qint64> SimStation::counterValue(const QByteArray &pattern, const SimPort &p) const {
    auto hours = [](double s) { return qint64(s / 3600.0); };
    if (pattern == "CPx")
        return hours(p.pluggedS);
    if (pattern == "CNx")
        return hours(p.noToolS);
    if (pattern == "CSx")
        return hours(p.sleepS);
    if (pattern == "CHx")
        return hours(p.hibernationS);
    if (pattern == "CWx")
        return hours(p.workS);
    if (pattern == "CCx")
        return p.sleepCycles;
    if (pattern == "CDx")
        return p.desolderCycles;
    if (pattern == "DCx")
        return p.dispensedCycles;
    if (pattern == "DLx")
        return qint64(p.dispensedDmm);
    return std::nullopt;
}

std::optional<Value> SimStation::readLive(const ResolvedCommand &cmd) {
    const QByteArray pattern = cmd.spec->pattern.toLatin1();
    if (pattern == "SMN")
        return Value::ofText(modelName());
    if (pattern == "SVR")
        return Value::ofText(softwareVersion());
    if (pattern == "SER")
        return Value::ofNumber(m_stationError);
    if (pattern == "FST")
        return Value::ofNumber(m_fusePresent ? 1 : 0);
    if (pattern == "FEE")
        return Value::ofNumber(m_ports.value(0).motor != 0 ? 1 : 0);
    if (pattern == "TT0") {
        int total = 0;
        for (const SimPort &p : m_ports)
            total += p.power;
        return Value::ofNumber(qRound(35.0 + total / 100.0));
    }
    if (cmd.port == 0)
        return std::nullopt;
    SimPort &p = m_ports[cmd.port - 1];
    // A deterministic wobble keeps the curves alive without making tests flaky. By default a
    // joint's fall and rise are left as the shape made them; a noisier station (a shape set's)
    // wobbles through its joints too, a slow swing with a faster ripple on it.
    const bool wobbles = p.tip > kAmbient + 5 && (!p.joint || m_noiseDuringJoints);
    const double noise = !wobbles ? 0
                         : m_noiseDuringJoints
                             ? m_noiseK * (0.6 * qSin(m_noisePhase * 3.1 + cmd.port) +
                                           0.4 * qSin(m_noisePhase * 23.7 + 2.0 * cmd.port))
                             : m_noiseK * qSin(m_noisePhase * 3.1 + cmd.port);
    if (pattern == "TTx") {
        if (p.joint) {
            ++p.joint->made.reads;
            p.joint->made.readDepthK =
                qMax(p.joint->made.readDepthK, p.joint->shape.belowTargetK(p.joint->elapsedMs));
        }
        return Value::ofNumber(qRound(p.tip + noise));
    }
    if (pattern == "PPx")
        return Value::ofNumber(p.power);
    if (pattern == "QTx")
        return Value::ofNumber(qRound(30.0 + p.power * 0.03));
    if (pattern == "CTx")
        return Value::ofNumber(p.tool);
    if (pattern == "PEx")
        return Value::ofNumber(p.error);
    if (pattern == "PSx")
        return Value::ofNumber(p.status + (p.cooling ? 10 : 0) + (p.suction ? 100 : 0) +
                               p.motor * 1000);
    if (pattern == "EDx") {
        const QByteArray code = p.status == 1   ? toolCode('D', cmd.port, p.tool)
                                : p.status == 2 ? toolCode('H', cmd.port, p.tool)
                                                : QByteArray();
        const qint64 minutes = code.isEmpty() ? kDisabledDelay : settingOr(code, kDisabledDelay);
        if (minutes == kDisabledDelay)
            return Value::ofNumber(0);
        return Value::ofNumber(qMax<qint64>(0, qCeil(minutes * 60.0 - p.secondsInStatus)));
    }
    if (pattern == "TAx") {
        const int flags = p.alarmFlags;
        if (cmd.spec->clearsOnRead.contains(family().name))
            p.alarmFlags = 0;
        return Value::ofNumber(flags);
    }
    if (auto c = counterValue(pattern, p))
        return Value::ofNumber(*c);
    return std::nullopt;
}

std::optional<QByteArray> SimStation::applyWrite(const ResolvedCommand &cmd, qint64 value) {
    const QByteArray pattern = cmd.spec->pattern.toLatin1();
    if (pattern == "PSx") {
        SimPort &p = m_ports[cmd.port - 1];
        p.cooling = value == 10;
        if (value != 10 && int(value) != p.status)
            setStatus(cmd.port, int(value));
        if (value == 0 && (p.tool == 5 || p.tool == 6)) {
            p.suction = true;
            ++p.desolderCycles;
        } else {
            p.suction = false;
        }
    } else if (pattern == "NVS") {
        for (int n = 1; n <= portCount(); ++n) {
            const QByteArray code = "ST" + QByteArray::number(n);
            m_savedSelected.insert(code, settingOr(code, 350));
        }
    } else if (pattern == "RST") {
        for (auto it = m_savedSelected.begin(); it != m_savedSelected.end(); ++it)
            setSetting(it.key(), it.value());
        for (int n = 1; n <= portCount(); ++n)
            m_ports[n - 1].tip = kAmbient;
    } else if (pattern == "IFE") {
        m_fuseIgnored = true;
    } else if (pattern == "STR" && !m_ports.isEmpty()) {
        m_ports[0].motor = 1;
        m_ports[0].dispenseLeftDmm = double(settingOr("LEN", 1000));
        ++m_ports[0].dispensedCycles;
    } else if (pattern == "STP" && !m_ports.isEmpty()) {
        m_ports[0].motor = 0;
    }
    return SimDevice::applyWrite(cmd, value);
}

} // namespace tipscope::sim
