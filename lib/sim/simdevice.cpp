#include "simdevice.h"

#include "protocol/datafield.h"

namespace tipscope::sim {

using namespace tipscope::protocol;

static constexpr int kNakFormat = 2;
static constexpr int kNakRange = 3;
static constexpr int kNakControl = 4;
static constexpr int kNakRobotMode = 5;
static constexpr int kMaxWriteLog = 10000;

SimDevice::SimDevice(const QString &familyName, int address)
    : m_catalog(Catalog::builtin())
    , m_family(m_catalog.family(familyName))
    , m_address(address) {
    Q_ASSERT(m_family);
    m_addressed = m_family->addressedByDefault;
    m_modelName = familyName;
}

void SimDevice::restoreFactorySettings() {
    m_settings.clear();
    for (const ResolvedCommand &r : m_catalog.expand(m_family->name, Direction::Write))
        if (r.spec->readable && r.factoryDefault)
            m_settings.insert(r.code, *r.factoryDefault);
}

std::optional<qint64> SimDevice::setting(const QByteArray &code) const {
    auto it = m_settings.constFind(code);
    if (it == m_settings.constEnd())
        return std::nullopt;
    return it.value();
}

Frame SimDevice::nak(const QByteArray &command, int code) const {
    Frame f;
    f.header = Header::Nak;
    f.command = command;
    f.data = encodeNumber(code).value_or("99999");
    return f;
}

Frame SimDevice::handle(const Frame &req) {
    if (req.header != Header::Read && req.header != Header::Write)
        return nak(req.command, kNakControl);
    // The robot guides list no robot mode for the feeder; stations refuse everything with it off.
    if (!m_robotMode && !m_family->isFeeder())
        return nak(req.command, kNakRobotMode);
    const Direction dir = req.header == Header::Read ? Direction::Read : Direction::Write;
    const auto cmd = m_catalog.resolve(m_family->name, req.command, dir);
    if (!cmd)
        return nak(req.command, kNakControl);
    return dir == Direction::Read ? answerRead(*cmd, req) : answerWrite(*cmd, req);
}

QByteArray SimDevice::encodeForAnswer(const ResolvedCommand &cmd, const Value &value) const {
    if (value.isText)
        return value.text.toLatin1();
    if (cmd.spec->special.contains(int(value.number)))
        return encodeNumber(value.number).value_or("99999");
    switch (cmd.spec->kind) {
    case ValueKind::Delay:
        return encodeDelay(int(value.number)).value_or("99.99");
    case ValueKind::Hex:
        return encodeHex(quint64(value.number));
    default:
        return encodeNumber(qBound(qint64(kNumberMin), value.number, qint64(kNumberMax))).value();
    }
}

Frame SimDevice::answerRead(const ResolvedCommand &cmd, const Frame &req) {
    if (!req.data.isEmpty())
        return nak(req.command, kNakFormat);
    std::optional<Value> value = readLive(cmd);
    if (!value) {
        const auto stored = setting(cmd.code);
        if (!stored)
            return nak(req.command, m_family->nakUndefined);
        value = Value::ofNumber(*stored);
    }
    Frame a;
    a.header = Header::Answer;
    a.command = req.command;
    a.data = encodeForAnswer(cmd, *value);
    return a;
}

Frame SimDevice::answerWrite(const ResolvedCommand &cmd, const Frame &req) {
    std::optional<qint64> value;
    switch (cmd.spec->kind) {
    case ValueKind::Action:
        if (req.data.size() != kNumberWidth)
            return nak(req.command, kNakFormat);
        if (req.data != cmd.spec->fixedData)
            return nak(req.command, kNakRange);
        value = 0;
        break;
    case ValueKind::Delay:
        value = parseDelay(req.data);
        if (!value)
            if (auto n = parseNumber(req.data); n && cmd.spec->special.contains(*n))
                value = *n;
        break;
    default:
        if (auto n = parseNumber(req.data))
            value = *n;
        break;
    }
    if (!value)
        return nak(req.command, kNakFormat);
    if (!validate(cmd, *value).isEmpty() || !withinDeviceLimits(cmd, *value))
        return nak(req.command, kNakRange);
    if (cmd.spec->readable && cmd.spec->kind != ValueKind::Action &&
        cmd.spec->kind != ValueKind::Flags)
        m_settings[cmd.code] = *value;
    if (m_acceptedWrites.size() >= kMaxWriteLog)
        m_acceptedWrites.removeFirst();
    m_acceptedWrites.append(QString::fromLatin1(cmd.code + '=' + req.data));
    const std::optional<QByteArray> answerData = applyWrite(cmd, *value);
    Frame a;
    a.header = Header::Answer;
    a.command = req.command;
    if (answerData)
        a.data = *answerData;
    else if (m_family->writeAnswerEchoesData)
        a.data = req.data;
    return a;
}

std::optional<QByteArray> SimDevice::applyWrite(const ResolvedCommand &cmd, qint64 value) {
    const QByteArray code = cmd.code;
    if (code == "SAD") {
        m_addressed = value != 0;
        if (value != 0)
            m_address = int(value);
    } else if (code == "RSP") {
        restoreFactorySettings();
        m_addressed = m_family->addressedByDefault;
        m_address = m_family->defaultAddress;
    }
    return std::nullopt;
}

bool SimDevice::withinDeviceLimits(const ResolvedCommand &cmd, qint64 value) const {
    if (cmd.spec->special.contains(int(value)))
        return true;
    if (!cmd.spec->limitMin.isEmpty()) {
        if (auto lo = setting(cmd.spec->limitMin.toLatin1()); lo && value < *lo)
            return false;
    }
    if (!cmd.spec->limitMax.isEmpty()) {
        if (auto hi = setting(cmd.spec->limitMax.toLatin1()); hi && value > *hi)
            return false;
    }
    return true;
}

} // namespace tipscope::sim
