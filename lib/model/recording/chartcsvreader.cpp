#include "model/recording/chartcsvreader.h"

#include "model/recording/chartcsvparser.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>
#endif

namespace tipscope::model {

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(ChartCsvReader)
};

constexpr int kWaitStepMs = 100;

QString tooLarge(qint64 limit) {
    return Tr::tr("the file is larger than %1 MB; replay reads files up to %1 MB").arg(limit >> 20);
}

// A FIFO, a character device or a socket: waited on before each read, a step at a time, so that
// a cancel is noticed while no data comes, and so that a FIFO nobody writes to yet is waited for
// rather than read as empty.
class Waiter {
public:
    explicit Waiter(int fd = -1)
        : m_fd(fd) {}
    // False when `keepGoing` said to stop.
    template <class KeepGoing> bool waitForData(KeepGoing keepGoing) const {
#ifdef Q_OS_UNIX
        if (m_fd < 0)
            return true;
        for (;;) {
            pollfd p{m_fd, POLLIN, 0};
            const int n = ::poll(&p, 1, kWaitStepMs);
            if (n != 0 && !(n < 0 && errno == EINTR))
                return true; // data, the writer's end, or an error that read() reports
            if (!keepGoing())
                return false;
        }
#else
        Q_UNUSED(keepGoing)
        return true;
#endif
    }

private:
    int m_fd;
};

// Opens `path` for streaming; a special file without blocking in open() (a FIFO without a
// writer would block there, out of reach of a cancel). The waiter for its reads, or nullopt with
// `why` set.
std::optional<Waiter> openForStreaming(QFile &file, const QFileInfo &info, QString *why) {
    file.setFileName(info.filePath());
#ifdef Q_OS_UNIX
    if (info.exists() && !info.isFile() && !info.isDir()) {
        const int fd = ::open(QFile::encodeName(info.filePath()).constData(),
                              O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) {
            *why = QString::fromLocal8Bit(std::strerror(errno));
            return std::nullopt;
        }
        if (!file.open(fd, QIODevice::ReadOnly | QIODevice::Unbuffered, QFile::AutoCloseHandle)) {
            ::close(fd);
            *why = file.errorString();
            return std::nullopt;
        }
        return Waiter(fd);
    }
#endif
    if (!file.open(QIODevice::ReadOnly)) {
        *why = file.errorString();
        return std::nullopt;
    }
    return Waiter();
}

std::optional<ChartRecordingData> parse(QIODevice &device, const Waiter &waiter, QString *error,
                                        const ChartCsvReader::Options &options) {
    ChartCsvParser parser;
    qint64 total = 0;
    const auto keepGoing = [&] { return !options.progress || options.progress(total); };
    const auto failed = [&](const QString &why) {
        *error = why;
        return std::nullopt;
    };
    QByteArray chunk(ChartCsvReader::kChunkBytes, Qt::Uninitialized);
    for (;;) {
        if (!waiter.waitForData(keepGoing))
            return failed(ChartCsvReader::cancelledText());
        // One byte past the limit at most: enough to know the file is over it.
        const qint64 want = qMin<qint64>(chunk.size(), options.maxBytes + 1 - total);
        const qint64 n = device.read(chunk.data(), want);
        if (n < 0)
            return failed(device.errorString());
        if (n == 0)
            break;
        total += n;
        if (total > options.maxBytes)
            return failed(tooLarge(options.maxBytes));
        if (!parser.feed(chunk.constData(), n))
            return failed(parser.error());
        if (parser.heldBytes() > 2 * total + ChartCsvReader::kMemorySlackBytes) {
            parser.fail(Tr::tr("its samples take %1 MB of memory after %2 MB read, more than "
                               "replay allows (twice the file's size); a recording TipScope "
                               "writes takes far less")
                            .arg(parser.heldBytes() >> 20)
                            .arg(total >> 20));
            return failed(parser.error());
        }
        if (!keepGoing())
            return failed(ChartCsvReader::cancelledText());
    }
    if (!parser.finish())
        return failed(parser.error());
    ChartRecordingData data = parser.take();
    data.recording->bytes = total;
    return data;
}
} // namespace

qint64 ChartRecording::memoryBytes() const {
    qint64 bytes = events.memoryBytes();
    if (telemetry)
        for (const ChartChannel &c : channels)
            if (const TelemetryBuffer *b = telemetry->buffer(c.key))
                bytes += b->memoryBytes();
    return bytes;
}

std::unique_ptr<ChartRecording> ChartRecordingData::assemble() {
    recording->telemetry = std::make_unique<Telemetry>();
    for (size_t i = 0; i < buffers.size(); ++i)
        recording->telemetry->adoptBuffer(recording->channels.at(qsizetype(i)).key,
                                          std::move(buffers[i]));
    buffers.clear();
    return std::move(recording);
}

QString ChartCsvReader::cancelledText() {
    return Tr::tr("reading was cancelled");
}

std::unique_ptr<ChartRecording> ChartCsvReader::read(QIODevice &device, QString *error,
                                                     const Options &options) {
    QString ignored;
    auto data = parse(device, Waiter(), error ? error : &ignored, options);
    return data ? data->assemble() : nullptr;
}

std::optional<ChartRecordingData> ChartCsvReader::readFileData(const QString &path, QString *error,
                                                               const Options &options) {
    QString why;
    const QFileInfo info(path);
    QFile file;
    std::optional<ChartRecordingData> result;
    // A regular file over the limit is refused at once; the limit also applies to the bytes
    // read, for files whose size says nothing (FIFOs, /proc) or that grow while read.
    if (info.isFile() && info.size() > options.maxBytes) {
        why = Tr::tr("the file is %1 MB; replay reads files up to %2 MB")
                  .arg(info.size() >> 20)
                  .arg(options.maxBytes >> 20);
    } else if (const auto waiter = openForStreaming(file, info, &why)) {
        result = parse(file, *waiter, &why, options);
    }
    if (!result && error)
        *error = info.fileName() + QStringLiteral(", ") + why;
    return result;
}

std::unique_ptr<ChartRecording> ChartCsvReader::readFile(const QString &path, QString *error,
                                                         const Options &options) {
    auto data = readFileData(path, error, options);
    return data ? data->assemble() : nullptr;
}

} // namespace tipscope::model
