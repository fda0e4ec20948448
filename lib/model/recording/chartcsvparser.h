// ChartCsvParser: the chart CSV (ChartCsvWriter's format) parsed as a stream of bytes, for
// ChartCsvReader. feed() takes any chunk, splits it into lines and parses each as it completes,
// so only one line is ever held as text; samples go straight into the channels' buffers and
// events into the recording. The first problem stops the parse and is kept as error(), with the
// line it was found on.
//
// What it holds is bounded: a line by kMaxLineBytes, comment lines by kMaxCommentLines, columns
// by kMaxColumns, samples by kMaxSamplesPerChannel per channel; heldBytes() says how much memory
// the recording takes so far, which the reader compares with the bytes it has read.
//
// Plain data, no QObject: a parser may run on any thread, and its result (take()) is shown on
// another.
#pragma once

#include "base/csv.h"
#include "model/recording/chartcsvreader.h"

#include <QMap>

namespace tipscope::model {

class ChartCsvParser {
public:
    ChartCsvParser();

    // False once the file cannot be replayed; error() says why. Chunks may split lines anywhere.
    bool feed(const char *data, qsizetype size);
    // The end of the file: parses a last line without a line break and checks there were rows.
    bool finish();
    [[nodiscard]] const QString &error() const { return m_error; }
    // Memory the recording holds so far: buffers, events and metadata.
    [[nodiscard]] qint64 heldBytes() const;
    // The line being parsed or last parsed (1-based), for messages.
    [[nodiscard]] qint64 lineNumber() const { return m_line; }

    // After finish() returned true: the recording, its samples not yet in a Telemetry.
    [[nodiscard]] ChartRecordingData take();

    // Sets error() to "line <n>: message" (or message alone before the first line); false.
    bool fail(const QString &message);

private:
    struct Column {
        int channel = -1; // -1: the events column
        SeriesFormat format;
    };

    bool line(QByteArrayView bytes);
    void comment(const QString &text);
    bool header(const base::csv::Cells &cells);
    void addChannel(const QString &id, int port);
    bool row(const base::csv::Cells &cells);
    bool channelValues(int channel, const base::csv::Cells &cells, QList<qint32> &out,
                       bool &present);
    bool events(qint64 ms, const base::csv::Cells &cells);
    // A gap cell ("port1 gap: line-down") of a known channel: marks the gap, true.
    bool gap(qint64 ms, const QString &cell);

    qint64 m_line = 0;
    qint64 m_comments = 0;
    QString m_error;
    QByteArray m_pending; // the start of a line whose end has not come yet
    bool m_firstChunk = true;
    QMap<QString, QMap<QString, QString>> m_meta; // channel id -> "# channel" fields
    qint64 m_metaBytes = 0;
    QList<Column> m_columns;
    QList<QList<int>> m_channelColumns; // per channel, its columns' indexes in m_columns
    QList<int> m_eventColumns;
    base::csv::Cells m_cells; // reused for every row
    QList<qint32> m_values;
    ChartRecordingData m_data;
    bool m_haveHeader = false;
};

} // namespace tipscope::model
