// TelemetryRecorder: turns the readings of a session's port and feeder models into telemetry
// samples, and records where the history has no samples.
//
// Each port's and feeder's history is kept under the device's identity (keyOf()), so a different
// device at the same address starts a history of its own, and the same device found again (after
// a reconnect, or after another device was on the line meanwhile) continues its old one. A
// sample is taken at every tip-temperature (or fed-length) reading, carrying the latest values
// of the other series. Gaps are recorded, not inferred: when the line goes down, when a reading
// gets no answer, and when the device stops being watched (disconnect, another device found),
// the history gets a gap that ends at its next sample. The recorder does not own the models.
#pragma once

#include "model/device/feedermodel.h"
#include "model/device/stationmodel.h"
#include "model/telemetry/telemetry.h"

#include <QObject>
#include <QPointer>
#include <functional>

namespace tipscope::model {

class TelemetryRecorder : public QObject {
    Q_OBJECT
public:
    using Clock = std::function<qint64()>; // milliseconds since the epoch

    TelemetryRecorder(Telemetry &telemetry, Clock clock, QObject *parent = nullptr);

    // The key of a port's history (`port` > 0) or a feeder's (0): the device's identity and the
    // channel, "<identity key>|port2" or "<identity key>|feeder".
    [[nodiscard]] static TelemetryKey keyOf(const DeviceModel &device, int port);
    [[nodiscard]] static TelemetryKey keyOf(const DeviceIdentity &device, int port);

    // Starts sampling the device's ports (a station) or its feed (a feeder).
    void watch(DeviceModel *device);
    // Stops sampling it; its histories get a gap (`cause`) from now on.
    void unwatch(DeviceModel *device, TelemetryGap::Cause cause);
    // Every watched history gets a gap from now on (the line went down).
    void markGaps(TelemetryGap::Cause cause);

private:
    void watchStation(StationModel *station);
    void watchFeeder(FeederModel *feeder);
    void gapOnNoAnswer(Parameter *reading, const TelemetryKey &key);
    [[nodiscard]] qint64 sampleTime(const TelemetryKey &key, const Parameter &tip) const;

    Telemetry &m_telemetry;
    Clock m_clock;
    // The keys each watched device writes, to mark their gaps.
    QHash<DeviceModel *, QList<TelemetryKey>> m_keys;
};

} // namespace tipscope::model
