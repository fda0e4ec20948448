// ChartCsvReader: reads a chart CSV (ChartCsvWriter's format) back into telemetry for replay and
// for tipscope-cli measure, so a recording is shown and measured by the same code as live data,
// with no device.
//
// Values are converted back to wire units with the units named in the column headers (a file
// written in °F replays exactly). Anything the reader cannot use fully is refused with a message
// that names the line and, where it helps, the column: no header row, an unknown unit, a row
// with the wrong number of cells, a bad time or number, rows out of time order, text that is not
// UTF-8, binary data, over-long lines, too many comment lines, and files or channels too large
// to hold (a day at 10 Hz per channel is what the live chart holds; replay takes up to twice
// that). Nothing partial is returned: a file either replays whole, every sample and event of it,
// or not at all.
//
// The file is read as a stream, a chunk at a time: the size limit applies to the bytes actually
// read (a FIFO or a growing file cannot slip past it), and the recording never takes more memory
// than twice the bytes read plus kMemorySlackBytes (a file packed more densely than TipScope
// writes is refused when it gets there). Options::progress follows the reading and can cancel it;
// a FIFO is waited on in short steps, so a cancel is answered even while no data comes.
// Reading creates no QObject until the last step, so it may run on a thread of its own
// (RecordingLoader); readFileData() stops before that step.
#pragma once

#include "model/chart/chartevents.h"
#include "model/chart/chartseries.h"

#include "base/outcome.h"
#include "model/telemetry/telemetry.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QIODevice;

namespace tipscope::model {

// A recording read back: its own telemetry (keys are the channel ids), channels and events.
struct ChartRecording {
    std::unique_ptr<Telemetry> telemetry;
    QList<ChartChannel> channels;
    ChartEvents events{ChartEvents::kUnbounded}; // every event of the file
    // The unit of the file's temperature columns: the unit its values are shown in.
    TemperatureUnit temperatureUnit = TemperatureUnit::Celsius;
    QString software; // "TipScope 0.1.0", as the header says
    qint64 rows = 0;
    qint64 firstMs = 0; // of the samples and events
    qint64 lastMs = 0;
    qint64 bytes = 0; // read from the file

    // Heap bytes of the samples and events.
    [[nodiscard]] qint64 memoryBytes() const;
};

// A recording before its samples go into a Telemetry (a QObject, which belongs to the thread that
// creates it): plain data that may be read on one thread and shown on another.
struct ChartRecordingData {
    std::unique_ptr<ChartRecording> recording = std::make_unique<ChartRecording>();
    std::vector<TelemetryBuffer> buffers; // one per channel, in the order of the channels

    // Moves the buffers into a Telemetry created in the calling thread.
    [[nodiscard]] std::unique_ptr<ChartRecording> assemble();
};

struct ChartCsvReadOptions {
    qint64 maxBytes = 1LL << 30;
    // Called with the bytes read so far after each chunk (and every 100 ms while a FIFO has
    // nothing to read); returning false cancels the read, which fails with cancelledText().
    std::function<bool(qint64 bytesRead)> progress;
};

class ChartCsvReader {
public:
    using Options = ChartCsvReadOptions;
    static constexpr qint64 kMaxFileBytes = 1LL << 30;
    static constexpr int kMaxLineBytes = 64 * 1024;
    // A recording has a few comment lines and one per channel; a file of comments is refused
    // early instead of being read to its end.
    static constexpr int kMaxCommentLines = 1024;
    static constexpr int kMaxSamplesPerChannel = 2 * TelemetryBuffer::kDefaultCapacity;
    static constexpr int kMaxColumns = 256;
    // Memory a recording may take besides twice the bytes read: the fixed costs of its buffers.
    static constexpr qint64 kMemorySlackBytes = 8 << 20;
    static constexpr int kChunkBytes = 64 * 1024;

    // The recording, or why the file cannot be replayed ("recording.csv, line 12: ...").
    [[nodiscard]] static base::Outcome<std::unique_ptr<ChartRecording>>
    readFile(const QString &path, const Options &options = {});
    // The same from an open device; the reason has no file name.
    [[nodiscard]] static base::Outcome<std::unique_ptr<ChartRecording>>
    read(QIODevice &device, const Options &options = {});
    // readFile() but for assemble(), for a thread other than the one that shows the recording.
    [[nodiscard]] static base::Outcome<ChartRecordingData>
    readFileData(const QString &path, const Options &options = {});
    // The error of a read that Options::progress cancelled.
    [[nodiscard]] static QString cancelledText();
};

} // namespace tipscope::model
