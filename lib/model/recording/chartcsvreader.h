// ChartCsvReader: reads a chart CSV (ChartCsvWriter's format) back into telemetry for replay,
// so a recording is shown by the same chart code as live data, with no device.
//
// Values are converted back to wire units with the units named in the column headers (a file
// written in °F replays exactly). Anything the reader cannot use fully is refused with a message
// that names the line and, where it helps, the column: no header row, an unknown unit, a row
// with the wrong number of cells, a bad time or number, rows out of time order, text that is not
// UTF-8, binary data, over-long lines, and files or channels too large to hold (a day at 10 Hz
// per channel is what the live chart holds; replay takes up to twice that). Nothing partial is
// returned: a file either replays whole or not at all.
#pragma once

#include "model/chart/chartevents.h"
#include "model/chart/chartseries.h"

#include "model/telemetry/telemetry.h"

#include <memory>

class QIODevice;

namespace tipscope::model {

// A recording read back: its own telemetry (keys are the channel ids), channels and events.
struct ChartRecording {
    std::unique_ptr<Telemetry> telemetry;
    QList<ChartChannel> channels;
    ChartEvents events{ChartEvents::kUnbounded}; // every event of the file
    QString software; // "TipScope 0.1.0", as the header says
    qint64 rows = 0;
    qint64 firstMs = 0; // of the samples and events
    qint64 lastMs = 0;
};

class ChartCsvReader {
public:
    static constexpr qint64 kMaxFileBytes = 1LL << 30;
    static constexpr int kMaxLineBytes = 64 * 1024;
    static constexpr int kMaxSamplesPerChannel = 2 * TelemetryBuffer::kDefaultCapacity;
    static constexpr int kMaxColumns = 256;

    // nullptr with `error` set ("recording.csv, line 12: ...") when the file cannot be replayed.
    [[nodiscard]] static std::unique_ptr<ChartRecording> readFile(const QString &path,
                                                                  QString *error);
    // The same from an open device; `error` has no file name.
    [[nodiscard]] static std::unique_ptr<ChartRecording> read(QIODevice &device, QString *error);
};

} // namespace tipscope::model
