#include "model/recording/recordingloader.h"

#include <QFileInfo>
#include <QThread>
#include <atomic>

namespace tipscope::model {

namespace {
constexpr int kProgressEveryMs = 100;
} // namespace

// Shared by the loader and its thread, so that neither outlives what the other still uses.
struct RecordingLoader::Job {
    QString path;
    qint64 maxBytes = 0;
    std::atomic<bool> cancel{false};
    std::atomic<qint64> bytes{0};
    // Written by the thread, read by the loader once the thread has finished.
    std::optional<ChartRecordingData> data;
    QString error;
};

RecordingLoader::RecordingLoader(QObject *parent)
    : QObject(parent) {
    m_progressTimer.setInterval(kProgressEveryMs);
    connect(&m_progressTimer, &QTimer::timeout, this, [this] {
        const qint64 bytes = bytesRead();
        if (bytes == m_lastReported)
            return;
        m_lastReported = bytes;
        Q_EMIT progress(bytes, m_total);
    });
}

RecordingLoader::~RecordingLoader() {
    stopThread();
}

qint64 RecordingLoader::bytesRead() const {
    return m_job ? m_job->bytes.load() : qMax<qint64>(0, m_lastReported);
}

void RecordingLoader::start(const QString &path, qint64 maxBytes) {
    stopThread();
    m_path = path;
    const QFileInfo info(path);
    m_total = info.isFile() ? info.size() : 0;
    m_lastReported = -1;
    m_cancelled = false;
    m_recording.reset();
    auto job = std::make_shared<Job>();
    job->path = path;
    job->maxBytes = maxBytes;
    m_job = job;
    m_thread = QThread::create([job] {
        ChartCsvReader::Options options;
        options.maxBytes = job->maxBytes;
        options.progress = [j = job.get()](qint64 bytes) {
            j->bytes = bytes;
            return !j->cancel;
        };
        auto read = ChartCsvReader::readFileData(job->path, options);
        if (read)
            job->data = std::move(read).value();
        else
            job->error = read.error();
    });
    // Emitted in the new thread: queued to this one.
    connect(m_thread, &QThread::finished, this, &RecordingLoader::onThreadFinished);
    m_thread->start();
    m_progressTimer.start();
}

void RecordingLoader::cancel() {
    if (m_job)
        m_job->cancel = true;
}

void RecordingLoader::stopThread() {
    if (!m_thread)
        return;
    m_job->cancel = true;
    m_thread->disconnect(this);
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_job.reset();
    m_progressTimer.stop();
}

void RecordingLoader::onThreadFinished() {
    const std::shared_ptr<Job> job = m_job;
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_job.reset();
    m_progressTimer.stop();
    m_lastReported = job->bytes;
    Q_EMIT progress(m_lastReported, m_total);
    if (job->data)
        m_recording = job->data->assemble(); // its Telemetry belongs to this thread
    m_cancelled = !job->data && job->cancel;
    Q_EMIT finished(job->data ? QString() : job->error);
}

std::unique_ptr<ChartRecording> RecordingLoader::takeRecording() {
    return std::move(m_recording);
}

} // namespace tipscope::model
