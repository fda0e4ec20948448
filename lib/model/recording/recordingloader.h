// RecordingLoader: reads a recording on a thread of its own, so that the window stays responsive
// whatever the file is (a gigabyte, a slow network share, a FIFO nobody writes to).
//
// start() begins reading (ChartCsvReader::readFileData() on a new thread); progress() reports the
// bytes read at most ten times a second; finished() comes once per start(), in the loader's
// thread, with an empty error when takeRecording() holds the recording (its Telemetry created in
// the loader's thread) or with why not. cancel() makes the read stop within a chunk, or 100 ms
// while a FIFO sends nothing; the loader then finishes with ChartCsvReader::cancelledText() and
// wasCancelled(). Starting again cancels a read still running. The destructor cancels and waits,
// so a loader may be deleted at any time.
#pragma once

#include "model/recording/chartcsvreader.h"

#include <QObject>
#include <QTimer>
#include <memory>

class QThread;

namespace tipscope::model {

class RecordingLoader : public QObject {
    Q_OBJECT
public:
    explicit RecordingLoader(QObject *parent = nullptr);
    ~RecordingLoader() override;

    void start(const QString &path, qint64 maxBytes = ChartCsvReader::kMaxFileBytes);
    void cancel();
    [[nodiscard]] bool isRunning() const { return m_job != nullptr; }
    [[nodiscard]] QString path() const { return m_path; }
    [[nodiscard]] qint64 bytesRead() const;
    // The file's size when known before reading (0 for a FIFO).
    [[nodiscard]] qint64 totalBytes() const { return m_total; }
    [[nodiscard]] bool wasCancelled() const { return m_cancelled; }
    // After finished() with an empty error: the recording, once.
    [[nodiscard]] std::unique_ptr<ChartRecording> takeRecording();

Q_SIGNALS:
    void progress(qint64 bytesRead, qint64 totalBytes);
    void finished(const QString &error);

private:
    struct Job;

    void stopThread();
    void onThreadFinished();

    std::shared_ptr<Job> m_job;
    QThread *m_thread = nullptr;
    QTimer m_progressTimer;
    QString m_path;
    qint64 m_total = 0;
    qint64 m_lastReported = -1;
    bool m_cancelled = false;
    std::unique_ptr<ChartRecording> m_recording;
};

} // namespace tipscope::model
