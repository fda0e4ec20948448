// One workspace line as JSON. Every field but the name and the connection may be left out and
// takes the default a new connection has; a field that is present must be of its kind and in its
// range, and a failure names it as "connection.baud".
#include "model/workspace/workspacefile.h"

#include "model/context/workcontextjson.h"

#include "link/tcptransport.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <cmath>

namespace tipscope::model {

namespace {
struct WorkspaceLineJsonTr {
    Q_DECLARE_TR_FUNCTIONS(WorkspaceFile)
};

using base::failure;
using base::Outcome;

// The line kinds in link::LineSettings::Kind's order, then a recording played as a line.
const QStringList kKinds = {QStringLiteral("serial"), QStringLiteral("tcp"), QStringLiteral("demo"),
                            QStringLiteral("recording")};
const int kRecordingKind = 3;
const QStringList kModes = {QStringLiteral("auto"), QStringLiteral("with"),
                            QStringLiteral("without")};
const QStringList kParities = {QStringLiteral("none"), QStringLiteral("even"),
                               QStringLiteral("odd")};
const QList<QSerialPort::Parity> kParityValues = {QSerialPort::NoParity, QSerialPort::EvenParity,
                                                  QSerialPort::OddParity};

// A JSON object's field, read with its dotted name for messages.
class Fields {
public:
    Fields(const QJsonObject &object, QString prefix)
        : m_object(object)
        , m_prefix(std::move(prefix)) {}

    [[nodiscard]] QString name(const QString &key) const { return m_prefix + key; }
    [[nodiscard]] bool has(const QString &key) const { return m_object.contains(key); }

    [[nodiscard]] Outcome<QString> text(const QString &key, const QString &fallback = {}) const {
        if (!has(key))
            return fallback;
        if (!m_object.value(key).isString())
            return failure(WorkspaceLineJsonTr::tr("%1 must be text").arg(name(key)));
        return m_object.value(key).toString().trimmed();
    }
    [[nodiscard]] Outcome<int> number(const QString &key, int fallback, int lo, int hi) const {
        if (!has(key))
            return fallback;
        const double v = m_object.value(key).toDouble(std::nan(""));
        if (!m_object.value(key).isDouble() || v != std::floor(v) || v < lo || v > hi)
            return failure(WorkspaceLineJsonTr::tr("%1 must be a whole number from %2 to %3")
                               .arg(name(key))
                               .arg(lo)
                               .arg(hi));
        return int(v);
    }
    [[nodiscard]] Outcome<bool> flag(const QString &key) const {
        if (has(key) && !m_object.value(key).isBool())
            return failure(WorkspaceLineJsonTr::tr("%1 must be true or false").arg(name(key)));
        return m_object.value(key).toBool();
    }
    [[nodiscard]] Outcome<int> oneOf(const QString &key, const QStringList &allowed,
                                     int fallback) const {
        const auto v = text(key, allowed.value(fallback));
        if (!v)
            return failure(v.error());
        if (!allowed.contains(v.value()))
            return failure(WorkspaceLineJsonTr::tr("%1 must be one of %2")
                               .arg(name(key), allowed.join(QStringLiteral(", "))));
        return int(allowed.indexOf(v.value()));
    }
    [[nodiscard]] Outcome<QJsonObject> object(const QString &key) const {
        if (has(key) && !m_object.value(key).isObject())
            return failure(WorkspaceLineJsonTr::tr("%1 must be an object").arg(name(key)));
        return m_object.value(key).toObject();
    }

private:
    QJsonObject m_object;
    QString m_prefix;
};

// Stops at the first failure of a field read: `TAKE(baud, f.number(...))`.
#define TAKE(var, expr)                                                                            \
    const auto var##_ = (expr);                                                                    \
    if (!var##_)                                                                                   \
        return failure(var##_.error());                                                            \
    const auto &var = var##_.value()

Outcome<void> readConnection(const QJsonObject &json, Session::Settings &session) {
    const Fields f(json, QStringLiteral("connection."));
    TAKE(kind, f.oneOf(QStringLiteral("kind"), kKinds, 0));
    link::LineSettings &line = session.line;
    if (kind == kRecordingKind) {
        TAKE(path, f.text(QStringLiteral("path")));
        if (path.isEmpty())
            return failure(WorkspaceLineJsonTr::tr("%1 must name the recording file")
                               .arg(f.name(QStringLiteral("path"))));
        session.recordingPath = path;
        return {};
    }
    line.kind = link::LineSettings::Kind(kind);
    if (line.kind == link::LineSettings::Kind::Serial) {
        TAKE(port, f.text(QStringLiteral("port")));
        if (port.isEmpty())
            return failure(WorkspaceLineJsonTr::tr("%1 must name the serial port")
                               .arg(f.name(QStringLiteral("port"))));
        TAKE(baud, f.number(QStringLiteral("baud"), 19200, 50, 4'000'000));
        TAKE(parity, f.oneOf(QStringLiteral("parity"), kParities, 0));
        TAKE(stopBits, f.number(QStringLiteral("stop_bits"), 1, 1, 2));
        line.serial.portName = port;
        line.serial.baudRate = baud;
        line.serial.parity = kParityValues.at(parity);
        line.serial.stopBits = stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop;
    } else if (line.kind == link::LineSettings::Kind::Tcp) {
        TAKE(address, f.text(QStringLiteral("address")));
        if (!link::TcpTransport::parseHostPort(address, &line.tcpHost, &line.tcpPort))
            return failure(
                WorkspaceLineJsonTr::tr("%1 must be HOST:PORT (for example 192.168.1.20:4001)")
                    .arg(f.name(QStringLiteral("address"))));
    }
    return {};
}

Outcome<void> readLink(const QJsonObject &json, link::LineSettings &line) {
    const Fields f(json, QStringLiteral("link."));
    TAKE(robot, f.number(QStringLiteral("robot_address"), 0, 0, 99));
    TAKE(turnaround, f.number(QStringLiteral("turnaround_ms"), 100, 5, 10'000));
    TAKE(retries, f.number(QStringLiteral("retries"), 2, 0, 10));
    TAKE(reconnect, f.number(QStringLiteral("reconnect_ms"), 1000, 100, 600'000));
    line.queue.robotAddress = robot;
    line.queue.turnaroundMs = turnaround;
    line.queue.retries = retries;
    line.reconnectIntervalMs = reconnect;
    return {};
}

Outcome<void> readAddressing(const QJsonObject &json, Session::Settings &session) {
    const Fields f(json, QStringLiteral("addressing."));
    TAKE(mode, f.oneOf(QStringLiteral("mode"), kModes, 0));
    TAKE(target, f.number(QStringLiteral("target"), 1, 0, 99));
    TAKE(scanAll, f.flag(QStringLiteral("scan_all")));
    session.addressing = Session::Addressing(mode);
    session.targetAddress = target;
    session.scanAllAddresses = scanAll;
    return {};
}

Outcome<QMap<int, QString>> readDeviceNames(const QJsonValue &value) {
    if (!value.isUndefined() && !value.isArray())
        return failure(WorkspaceLineJsonTr::tr("devices must be a list"));
    QMap<int, QString> names;
    const QJsonArray list = value.toArray();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const Fields f(list.at(i).toObject(), QStringLiteral("devices[%1].").arg(i));
        if (!list.at(i).isObject())
            return failure(WorkspaceLineJsonTr::tr("devices[%1] must be an object").arg(i));
        const QJsonValue given = list.at(i).toObject().value(QStringLiteral("address"));
        const bool unaddressed = given.isNull();
        if (given.isUndefined())
            return failure(WorkspaceLineJsonTr::tr(
                               "%1 must be an address from 0 to 99, or null for the device "
                               "without addresses")
                               .arg(f.name(QStringLiteral("address"))));
        TAKE(address,
             unaddressed ? Outcome<int>(-1) : f.number(QStringLiteral("address"), -1, 0, 99));
        TAKE(name, f.text(QStringLiteral("name")));
        if (name.isEmpty())
            return failure(WorkspaceLineJsonTr::tr("%1 must not be empty")
                               .arg(f.name(QStringLiteral("name"))));
        const int key = unaddressed ? -1 : address;
        if (names.contains(key))
            return failure(
                WorkspaceLineJsonTr::tr("devices[%1] names a device named before").arg(i));
        names.insert(key, name);
    }
    return names;
}

QJsonObject connectionJson(const Session::Settings &session) {
    if (!session.recordingPath.isEmpty())
        return {{QStringLiteral("kind"), kKinds.at(kRecordingKind)},
                {QStringLiteral("path"), session.recordingPath}};
    const link::LineSettings &line = session.line;
    QJsonObject o{{QStringLiteral("kind"), kKinds.value(int(line.kind))}};
    if (line.kind == link::LineSettings::Kind::Serial) {
        o.insert(QStringLiteral("port"), line.serial.portName);
        o.insert(QStringLiteral("baud"), line.serial.baudRate);
        o.insert(QStringLiteral("parity"),
                 kParities.value(qMax(0, int(kParityValues.indexOf(line.serial.parity)))));
        o.insert(QStringLiteral("stop_bits"), line.serial.stopBits == QSerialPort::TwoStop ? 2 : 1);
    } else if (line.kind == link::LineSettings::Kind::Tcp) {
        o.insert(QStringLiteral("address"),
                 QStringLiteral("%1:%2").arg(line.tcpHost).arg(line.tcpPort));
    }
    return o;
}

QJsonArray deviceNamesJson(const QMap<int, QString> &names) {
    QJsonArray list;
    for (auto it = names.cbegin(); it != names.cend(); ++it)
        list.append(QJsonObject{
            {QStringLiteral("address"), it.key() < 0 ? QJsonValue() : QJsonValue(it.key())},
            {QStringLiteral("name"), it.value()}});
    return list;
}

} // namespace

QJsonObject workspaceLineToJson(const WorkspaceLine &line) {
    const Session::Settings &s = line.session;
    QJsonObject o{{QStringLiteral("name"), line.name},
                  {QStringLiteral("cell"), line.cell},
                  {QStringLiteral("location"), line.location},
                  {QStringLiteral("connection"), connectionJson(s)},
                  {QStringLiteral("link"),
                   QJsonObject{{QStringLiteral("robot_address"), s.line.queue.robotAddress},
                               {QStringLiteral("turnaround_ms"), s.line.queue.turnaroundMs},
                               {QStringLiteral("retries"), s.line.queue.retries},
                               {QStringLiteral("reconnect_ms"), s.line.reconnectIntervalMs}}},
                  {QStringLiteral("addressing"),
                   QJsonObject{{QStringLiteral("mode"), kModes.value(int(s.addressing))},
                               {QStringLiteral("target"), s.targetAddress},
                               {QStringLiteral("scan_all"), s.scanAllAddresses}}},
                  {QStringLiteral("devices"), deviceNamesJson(line.deviceNames)},
                  {QStringLiteral("context"), workContextToJson(line.context)}};
    if (line.jointLimits)
        o.insert(QStringLiteral("joint_limits"), line.jointLimits->toJson());
    return o;
}

Outcome<WorkspaceLine> workspaceLineFromJson(const QJsonObject &json) {
    const Fields f(json, QString());
    WorkspaceLine line;
    TAKE(name, f.text(QStringLiteral("name")));
    if (name.isEmpty())
        return failure(WorkspaceLineJsonTr::tr("every line needs a name"));
    line.name = name;
    TAKE(cell, f.text(QStringLiteral("cell")));
    TAKE(location, f.text(QStringLiteral("location")));
    line.cell = cell;
    line.location = location;
    if (!f.has(QStringLiteral("connection")))
        return failure(WorkspaceLineJsonTr::tr("connection is missing"));
    TAKE(connection, f.object(QStringLiteral("connection")));
    TAKE(linkJson, f.object(QStringLiteral("link")));
    TAKE(addressing, f.object(QStringLiteral("addressing")));
    for (const Outcome<void> &read :
         {readConnection(connection, line.session), readLink(linkJson, line.session.line),
          readAddressing(addressing, line.session)})
        if (!read)
            return failure(read.error());
    TAKE(names, readDeviceNames(json.value(QStringLiteral("devices"))));
    line.deviceNames = names;
    if (f.has(QStringLiteral("joint_limits"))) {
        TAKE(limitsJson, f.object(QStringLiteral("joint_limits")));
        const auto limits = JointLimitRules::fromJson(limitsJson);
        if (!limits)
            return failure(QStringLiteral("joint_limits: %1").arg(limits.error()));
        line.jointLimits = limits.value();
    }
    TAKE(contextJson, f.object(QStringLiteral("context")));
    const auto context = workContextFromJson(contextJson);
    if (!context)
        return failure(QStringLiteral("context: %1").arg(context.error()));
    line.context = context.value();
    return line;
}

} // namespace tipscope::model
