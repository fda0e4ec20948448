#include "simfeeder.h"

namespace tipscope::sim {

using namespace tipscope::protocol;

namespace {
constexpr int kDiscontinuous = 2;
constexpr double kDmmPerMetre = 10000.0;
} // namespace

SimFeeder::SimFeeder(int address)
    : SimDevice(QStringLiteral("SFR"), address) {
    setModelName(QStringLiteral("SFR-A"));
    setSoftwareVersion(QStringLiteral("0030195"));
    restoreFactorySettings();
}

void SimFeeder::advance(int ms) {
    const double dt = ms / 1000.0;
    m_pluggedTotalS += dt;
    m_pluggedPartialS += dt;
    if (m_direction == 0)
        return;
    double moved = dt * double(settingOr("SPD", 100));
    if (!m_loading && settingOr("MOD", 1) == kDiscontinuous) {
        const double left = double(settingOr("LEN", 200)) - m_fedDmm;
        if (moved >= left) {
            moved = qMax(0.0, left);
            m_direction = 0;
        }
    }
    m_fedDmm += moved;
    m_feedingTotalS += dt;
    m_feedingPartialS += dt;
    if (m_direction >= 0) {
        m_lengthTotalDmm += moved;
        m_lengthPartialDmm += moved;
    }
}

void SimFeeder::startFeed(bool forward) {
    m_fedDmm = 0;
    m_loading = false;
    m_direction = m_error != 0 ? 0 : forward ? 1 : -1;
}

std::optional<Value> SimFeeder::readLive(const ResolvedCommand &cmd) {
    const QByteArray code = cmd.code;
    auto hours = [](double s) { return Value::ofNumber(qint64(s / 3600.0)); };
    auto metres = [](double dmm) { return Value::ofNumber(qint64(dmm / kDmmPerMetre)); };
    if (code == "SMN")
        return Value::ofText(modelName());
    if (code == "FDS")
        return Value::ofNumber(isFeeding() ? 1 : 0);
    if (code == "FDL")
        return Value::ofNumber(qint64(m_fedDmm));
    if (code == "ECV")
        return Value::ofNumber(m_error);
    if (code == "CPT")
        return hours(m_pluggedTotalS);
    if (code == "CPP")
        return hours(m_pluggedPartialS);
    if (code == "CFT")
        return hours(m_feedingTotalS);
    if (code == "CFP")
        return hours(m_feedingPartialS);
    if (code == "CTT")
        return metres(m_lengthTotalDmm);
    if (code == "CTP")
        return metres(m_lengthPartialDmm);
    return std::nullopt;
}

std::optional<QByteArray> SimFeeder::applyWrite(const ResolvedCommand &cmd, qint64 value) {
    const QByteArray code = cmd.code;
    if (code == "SFD") {
        startFeed(value == 1);
    } else if (code == "SSD") {
        stopFeed();
    } else if (code == "SLD") {
        m_loading = value == 1;
        m_direction = m_loading ? 1 : 0;
        m_fedDmm = 0;
    } else if (code == "ECV") {
        m_error = 0;
        return QByteArray("00001");
    } else if (code == "CPP") {
        m_pluggedPartialS = 0;
    } else if (code == "CFP") {
        m_feedingPartialS = 0;
    } else if (code == "CTP") {
        m_lengthPartialDmm = 0;
    }
    return SimDevice::applyWrite(cmd, value);
}

} // namespace tipscope::sim
