// What a chart shows, without Qt Charts: the channels (a port or a feeder with its telemetry
// key and what a CSV header says about it), how each telemetry series turns from wire units into
// what people read (°C or °F, %, mm, mm/s, from the catalog's units), and the traces a pane
// draws (one series of one channel, with its colour, dash and axis).
//
// Plain values; the page builds them from the session's devices (live) or from a CSV header
// (replay), so live and replay charts are drawn by the same code.
#pragma once

#include "model/context/deviceidentity.h"
#include "model/device/displayunits.h"
#include "model/telemetry/telemetry.h"

#include <QColor>
#include <QList>
#include <QString>
#include <optional>

namespace tipscope::model {
class Session;
}

namespace tipscope::model {

enum class ChartAxis { Left, Right };

struct SeriesFormat {
    double scale = 1; // display = wire * scale + offset
    double offset = 0;
    int decimals = 0;
    QString unit; // "°C", "%", "mm", "mm/s", or empty for a plain number
    ChartAxis axis = ChartAxis::Left;
    bool plotted = true; // status and feeding are numbers for the CSV, not curves

    [[nodiscard]] double toDisplay(qint32 wire) const { return double(wire) * scale + offset; }
    // nullopt when `display` is not finite or its wire value does not fit an int32.
    [[nodiscard]] std::optional<qint32> toWire(double display) const;
    [[nodiscard]] QString format(double display) const; // "350 °C", "12.5 %"
};

// The format of a telemetry series ("tip", "setpoint", "power", "status", "fed", "speed",
// "feeding"); an unknown series is a plain number.
[[nodiscard]] SeriesFormat seriesFormat(const QString &series, TemperatureUnit unit);
// The person-readable name of a series ("Tip", "Setpoint", "Power", "Fed length"...).
[[nodiscard]] QString seriesTitle(const QString &series);
// A curve's name in a legend, a whole phrase in each language: "P1 tip" on port 1, "tip" for a
// kind of curve, a feeder's or the station's transformer (port 0).
[[nodiscard]] QString traceName(const QString &series, int port);

struct ChartChannel {
    TelemetryKey key;        // its history (TelemetryRecorder::keyOf(); the id in a replay)
    QString id;              // CSV column prefix ("port1", "feeder"): letters and digits
    int port = 0;            // 0 for a feeder
    QString title;           // "Port 1", "Feeder"
    QString deviceModel;     // "DME-4C"
    QString deviceName;      // "DME-4C at 01", as the event log names the device
    QString address;         // "01"
    QString softwareVersion; // the device's
    DeviceIdentity device;   // whose history this is; empty in a replay
    QString tool;            // "T245", empty when not known
    QStringList series;      // the telemetry series, in buffer order
    // The port's alarm limits (HAx, LAx) in wire units (°C), when known.
    std::optional<qint32> highAlarm;
    std::optional<qint32> lowAlarm;

    [[nodiscard]] bool isFeeder() const { return port == 0; }
};

// The channels of the session's station ports and feeder, in that order, with the tools and
// alarm limits as last read (call again to refresh them).
[[nodiscard]] QList<ChartChannel> sessionChannels(Session &session);

struct ChartTrace {
    int channel = 0; // index into the channel list
    QString series;
    QString name; // legend text ("P1 tip")
    QColor color;
    Qt::PenStyle style = Qt::SolidLine;
    SeriesFormat format;
};

// The traces of a pane: tip, setpoint and power of each port channel in `channels` (by index),
// or fed length and speed of a feeder channel. Colours follow the port, so overlaid ports differ
// and a port keeps its colour in its own pane.
[[nodiscard]] QList<ChartTrace> tracesFor(const QList<ChartChannel> &channels,
                                          const QList<int> &which, TemperatureUnit unit,
                                          bool hardware = false);
// The transistor and transformer temperatures, which a pane draws only when asked (`hardware`
// above); the transformer's is the station's, drawn once per station.
[[nodiscard]] bool isHardwareSeries(const QString &series);
[[nodiscard]] QColor portColor(int port);

} // namespace tipscope::model
