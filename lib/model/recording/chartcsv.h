// ChartCsvWriter: the self-describing CSV that chart exports and recordings are written in, and
// that replay reads back (ChartCsvReader).
//
// The file starts with '#' lines naming the format, the software, the time convention and each
// channel (device model, address, device software, port, tool), then one header row: "time",
// one column per series and channel with its unit ("port1 tip [°C]", "port1 power [%]",
// "port1 status"), and "events". Each row is one instant: an ISO 8601 UTC time with
// milliseconds, the values of the channels sampled at that instant in display units (cells of
// channels without a sample there are empty), and at most one event marker or gap. UTF-8, '\n' line
// ends, '.' as the decimal point whatever the locale, so a spreadsheet and a script read the same.
//
// The writer does not own the device. Rows must be written in non-decreasing time.
#pragma once

#include "model/chart/chartevents.h"
#include "model/chart/chartseries.h"

#include "model/telemetry/telemetry.h"

#include <QTextStream>
#include <optional>

class QIODevice;

namespace tipscope::model {

namespace chartcsv {
inline constexpr char kMagic[] = "# TipScope chart data, format 1";
inline constexpr char kTimeColumn[] = "time";
inline constexpr char kEventsColumn[] = "events";
// The kind token of a gap in the events column: "port1 gap: line-down" starts a gap in port1's
// history at that row's time, which its next sample ends.
inline constexpr char kGapKind[] = "gap";
// "port1 tip [°C]" or "port1 status".
[[nodiscard]] QString columnName(const QString &channelId, const QString &series,
                                 const SeriesFormat &format);
[[nodiscard]] QString timeText(qint64 ms);
} // namespace chartcsv

// The new samples of one channel, all series sampled together (as Telemetry stores them).
struct ChannelRows {
    QList<qint64> times;
    QList<QList<qint32>> values; // values[i]: one per series, buffer order
    QList<TelemetryGap> gaps;    // the gaps that start in the window
};

class ChartCsvWriter {
public:
    ChartCsvWriter(QIODevice &device, const QList<ChartChannel> &channels, TemperatureUnit unit);

    bool writeHeader(const QString &softwareVersion);
    // Every sample of [t0, t1) of every channel, and the events of that window, read a slice
    // at a time so an export of a day does not copy the day into memory at once.
    bool writeWindow(const Telemetry &telemetry, const ChartEvents &events, qint64 t0, qint64 t1);
    // Rows for samples and events gathered by a caller (the recorder); rows[i] is channel i's.
    bool writeRows(const QList<ChannelRows> &rows, const QList<ChartEvent> &events);

    [[nodiscard]] qint64 rowsWritten() const { return m_rows; }
    [[nodiscard]] QString errorString() const;

    // Where an export of a window starting at `t0` begins to hold every sample, when some
    // channel's history before that is only summaries (TelemetryBuffer::fullRateFrom(): exports
    // hold samples, never summaries); nullopt when the export holds every sample of the window.
    [[nodiscard]] static std::optional<qint64>
    fullRateFrom(const Telemetry &telemetry, const QList<ChartChannel> &channels, qint64 t0);
    // The samples of [t0, t1) of `channel` from the telemetry, for writeRows().
    [[nodiscard]] static ChannelRows collect(const Telemetry &telemetry,
                                             const ChartChannel &channel, qint64 t0, qint64 t1);

private:
    void writeRow(qint64 timeMs, const QList<const QList<qint32> *> &cells, const QString &event);

    QIODevice &m_device;
    QTextStream m_out;
    QList<ChartChannel> m_channels;
    QList<QList<SeriesFormat>> m_formats; // per channel, per series
    qint64 m_rows = 0;
};

} // namespace tipscope::model
