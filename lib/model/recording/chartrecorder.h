// ChartRecorder: continuous recording of live telemetry to a chart CSV file the user chose.
//
// start() writes the header and from then on every sample the telemetry accepts for the
// recorded channels, and every event marker it is given, is appended in time order, a batch per
// Telemetry::samplesAdded (at most 20 a second), flushed each time so a crash loses at most a
// batch. Each channel keeps a cursor (the last time written and how many samples at that time),
// so a sample is written exactly once even when two batches share a millisecond. Events are
// never written before rows already in the file, so the file stays in time order even when an
// event reaches the recorder after a batch holding samples stamped later than it.
//
// A header that cannot be written whole (a full disk, a file size limit) leaves no file. A failed
// write later stops the recording and reports why through failed(); the file keeps every batch
// written whole and ends with the last of them. The recorder reads the telemetry; it does not own
// it, and stops writing if the telemetry is destroyed first (the main window destroys the session
// before its pages).
#pragma once

#include "model/recording/chartcsv.h"

#include <QFile>
#include <QObject>
#include <QPointer>
#include <memory>

namespace tipscope::model {

class ChartRecorder : public QObject {
    Q_OBJECT
public:
    explicit ChartRecorder(Telemetry &telemetry, QObject *parent = nullptr);
    ~ChartRecorder() override;

    // Empty when recording started; otherwise why not (the file could not be created...).
    QString start(const QString &path, const QList<ChartChannel> &channels, TemperatureUnit unit,
                  const QString &softwareVersion);
    void stop();
    [[nodiscard]] bool isRecording() const { return m_writer != nullptr; }
    [[nodiscard]] QString path() const { return m_file.fileName(); }
    [[nodiscard]] qint64 rowsWritten() const { return m_writer ? m_writer->rowsWritten() : m_rows; }

    void addEvent(const ChartEvent &event);
    // Writes what has arrived since the last batch (also done on samplesAdded and by stop()).
    void flush();

Q_SIGNALS:
    void failed(const QString &reason);

private:
    struct Cursor {
        qint64 time = 0;
        qsizetype doneAtTime = 0; // samples at `time` already written
        qint64 gapsUntil = -1;    // the start of the last gap written
    };

    QPointer<Telemetry> m_telemetry;
    QFile m_file;
    std::unique_ptr<ChartCsvWriter> m_writer;
    QList<ChartChannel> m_channels;
    QList<Cursor> m_cursors;
    QList<ChartEvent> m_pendingEvents;
    qint64 m_lastWrittenMs = 0;
    qint64 m_rows = 0;
    qint64 m_wholeBytes = 0; // the file's size after the last batch written whole
    qint64 m_wholeRows = 0;  // and the rows in it
};

} // namespace tipscope::model
