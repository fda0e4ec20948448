#include "model/live/telemetryrecorder.h"

#include <cmath>

namespace tipscope::model {

namespace {
// The hardware temperatures (QTx, TT0) are read with the status values, every few seconds; a
// sample carries their latest reading. The transformer's is the station's, in every port.
const QStringList kPortSeries = {QStringLiteral("tip"),        QStringLiteral("setpoint"),
                                 QStringLiteral("power"),      QStringLiteral("status"),
                                 QStringLiteral("transistor"), QStringLiteral("transformer")};
const QStringList kFeederSeries = {QStringLiteral("fed"), QStringLiteral("speed"),
                                   QStringLiteral("feeding")};

// A value the sample can carry: its reading, or 0 for one that cannot be read (a failed write's
// value, a command the family lacks, a read the station refuses); nullopt while the first reading
// is still to come. An auxiliary value (the hardware temperatures) is not waited for once a read
// of it went unanswered either: a value the station cannot give costs only itself, never the
// samples of the tip (and so the charts and the joints).
enum class Need { Essential, Auxiliary };
std::optional<qint32> carried(const Parameter *p, Need need = Need::Essential) {
    if (!p)
        return 0;
    if (const auto v = p->number())
        return qint32(*v);
    const bool cannotBeRead = p->state() == Parameter::State::Failed || p->isRefused() ||
                              (need == Need::Auxiliary && p->lastReadFailed());
    return cannotBeRead ? std::optional<qint32>(0) : std::nullopt;
}
} // namespace

TelemetryRecorder::TelemetryRecorder(Telemetry &telemetry, Clock clock, QObject *parent)
    : QObject(parent)
    , m_telemetry(telemetry)
    , m_clock(std::move(clock)) {}

TelemetryKey TelemetryRecorder::keyOf(const DeviceModel &device, int port) {
    return keyOf(device.identity(), port);
}

TelemetryKey TelemetryRecorder::keyOf(const DeviceIdentity &device, int port) {
    const QString channel =
        port > 0 ? QStringLiteral("port%1").arg(port) : QStringLiteral("feeder");
    return device.key() + QLatin1Char('|') + channel;
}

void TelemetryRecorder::watch(DeviceModel *device) {
    if (auto *station = qobject_cast<StationModel *>(device))
        watchStation(station);
    else if (auto *feeder = qobject_cast<FeederModel *>(device))
        watchFeeder(feeder);
}

void TelemetryRecorder::unwatch(DeviceModel *device, TelemetryGap::Cause cause) {
    const qint64 now = m_clock();
    for (const TelemetryKey &key : m_keys.take(device))
        m_telemetry.markGap(key, now, cause);
    // The device's readings stay connected to nothing of ours.
    for (Parameter *p : device->parameters())
        p->disconnect(this);
}

void TelemetryRecorder::markGaps(TelemetryGap::Cause cause) {
    const qint64 now = m_clock();
    for (const QList<TelemetryKey> &keys : std::as_const(m_keys))
        for (const TelemetryKey &key : keys)
            m_telemetry.markGap(key, now, cause);
}

void TelemetryRecorder::gapOnNoAnswer(Parameter *reading, const TelemetryKey &key) {
    connect(reading, &Parameter::readFailed, this,
            [this, key] { m_telemetry.markGap(key, m_clock(), TelemetryGap::Cause::NoAnswer); });
}

// A sample is stamped at the instant its tip reading describes, not when the answer was decoded:
// a joint's start and recovery are measured against the station's own moments (and a customer's
// clock), and the answer's bytes and the event loop would make every reading look younger.
// Never before the buffer's last sample: queries binary-search on time.
qint64 TelemetryRecorder::sampleTime(const TelemetryKey &key, const Parameter &tip) const {
    const qint64 at = m_clock() - std::llround(tip.reportedAgeMs());
    const TelemetryBuffer *buffer = m_telemetry.buffer(key);
    return buffer && buffer->size() + buffer->summaryCount() > 0 ? qMax(at, buffer->lastTime())
                                                                 : at;
}

void TelemetryRecorder::watchStation(StationModel *station) {
    using protocol::Role;
    for (PortModel *port : station->ports()) {
        const TelemetryKey key = keyOf(*station, port->number());
        m_telemetry.ensureBuffer(key, kPortSeries);
        m_keys[station].append(key);
        Parameter *tip = port->parameter(Role::TipTemperature);
        if (!tip)
            continue;
        gapOnNoAnswer(tip, key);
        // A sample per tip-temperature reading; the other series carry their latest values.
        connect(tip, &Parameter::updated, this, [this, station, port, key, tip] {
            // A series starting at 0 before its first reading would draw a false drop and spoil
            // the measurements: record once the setpoint, power, status and temperatures are
            // known (a status of 0 is "working"). A status the station does not give is taken
            // as working, as the joints cannot be told from rests without it.
            const auto status = carried(port->parameter(Role::Status), Need::Auxiliary);
            const auto setpoint = carried(port->parameter(Role::Setpoint));
            const auto power = carried(port->parameter(Role::Power));
            const auto transistor =
                carried(port->parameter(Role::TransistorTemperature), Need::Auxiliary);
            const auto transformer =
                carried(station->parameter(Role::TransformerTemperature), Need::Auxiliary);
            if (!status || !setpoint || !power || !transistor || !transformer)
                return;
            m_telemetry.append(key, sampleTime(key, *tip),
                               {qint32(port->tipTemperature().value_or(0)), *setpoint, *power,
                                *status, *transistor, *transformer});
        });
    }
}

void TelemetryRecorder::watchFeeder(FeederModel *feeder) {
    using protocol::Role;
    const TelemetryKey key = keyOf(*feeder, 0);
    m_telemetry.ensureBuffer(key, kFeederSeries);
    m_keys[feeder].append(key);
    Parameter *fedLength = feeder->parameter(Role::FedLength);
    if (!fedLength)
        return;
    gapOnNoAnswer(fedLength, key);
    connect(fedLength, &Parameter::updated, this, [this, feeder, fedLength, key] {
        // As for the ports: the speed is a setting read less often than the fed length, and a
        // 0 before its first reading would draw a false step and spoil the window's mean.
        const auto fed = carried(fedLength);
        const auto speed = carried(feeder->parameter(Role::FeedSpeed));
        const auto feeding = carried(feeder->parameter(Role::Feeding));
        if (!fed || !speed || !feeding)
            return;
        m_telemetry.append(key, m_clock(), {*fed, *speed, *feeding == 1 ? 1 : 0});
    });
}

} // namespace tipscope::model
