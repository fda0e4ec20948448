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

using base::failure;
using base::Outcome;

namespace {
struct ChartCsvReaderTr {
    Q_DECLARE_TR_FUNCTIONS(ChartCsvReader)
};

constexpr int kWaitStepMs = 100;

QString tooLarge(qint64 limit) {
    return ChartCsvReaderTr::tr("the file is larger than %1 MB; replay reads files up to %1 MB")
        .arg(limit >> 20);
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
// writer would block there, out of reach of a cancel). The waiter for its reads, or why not.
Outcome<Waiter> openForStreaming(QFile &file, const QFileInfo &info) {
    file.setFileName(info.filePath());
#ifdef Q_OS_UNIX
    if (info.exists() && !info.isFile() && !info.isDir()) {
        const int fd = ::open(QFile::encodeName(info.filePath()).constData(),
                              O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0)
            return failure(QString::fromLocal8Bit(std::strerror(errno)));
        if (!file.open(fd, QIODevice::ReadOnly | QIODevice::Unbuffered, QFile::AutoCloseHandle)) {
            ::close(fd);
            return failure(file.errorString());
        }
        return Waiter(fd);
    }
#endif
    if (!file.open(QIODevice::ReadOnly))
        return failure(file.errorString());
    return Waiter();
}

Outcome<ChartRecordingData> parse(QIODevice &device, const Waiter &waiter,
                                  const ChartCsvReader::Options &options) {
    ChartCsvParser parser;
    qint64 total = 0;
    const auto keepGoing = [&] { return !options.progress || options.progress(total); };
    QByteArray chunk(ChartCsvReader::kChunkBytes, Qt::Uninitialized);
    for (;;) {
        if (!waiter.waitForData(keepGoing))
            return failure(ChartCsvReader::cancelledText());
        // One byte past the limit at most: enough to know the file is over it.
        const qint64 want = qMin<qint64>(chunk.size(), options.maxBytes + 1 - total);
        const qint64 n = device.read(chunk.data(), want);
        if (n < 0)
            return failure(device.errorString());
        if (n == 0)
            break;
        total += n;
        if (total > options.maxBytes)
            return failure(tooLarge(options.maxBytes));
        if (!parser.feed(chunk.constData(), n))
            return failure(parser.error());
        if (parser.heldBytes() > 2 * total + ChartCsvReader::kMemorySlackBytes) {
            parser.fail(
                ChartCsvReaderTr::tr("its samples take %1 MB of memory after %2 MB read, more than "
                                     "replay allows (twice the file's size); a recording TipScope "
                                     "writes takes far less")
                    .arg(parser.heldBytes() >> 20)
                    .arg(total >> 20));
            return failure(parser.error());
        }
        if (!keepGoing())
            return failure(ChartCsvReader::cancelledText());
    }
    if (!parser.finish())
        return failure(parser.error());
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
    return ChartCsvReaderTr::tr("reading was cancelled");
}

// The recording assembled in the calling thread, or the reason `data` has.
static Outcome<std::unique_ptr<ChartRecording>> assembled(Outcome<ChartRecordingData> data) {
    if (!data)
        return failure(data.error());
    return std::move(data).value().assemble();
}

Outcome<std::unique_ptr<ChartRecording>> ChartCsvReader::read(QIODevice &device,
                                                              const Options &options) {
    return assembled(parse(device, Waiter(), options));
}

Outcome<ChartRecordingData> ChartCsvReader::readFileData(const QString &path,
                                                         const Options &options) {
    const QFileInfo info(path);
    const auto named = [&info](const QString &why) {
        return failure(info.fileName() + QStringLiteral(", ") + why);
    };
    // A regular file over the limit is refused at once; the limit also applies to the bytes
    // read, for files whose size says nothing (FIFOs, /proc) or that grow while read.
    if (info.isFile() && info.size() > options.maxBytes)
        return named(ChartCsvReaderTr::tr("the file is %1 MB; replay reads files up to %2 MB")
                         .arg(info.size() >> 20)
                         .arg(options.maxBytes >> 20));
    QFile file;
    const auto waiter = openForStreaming(file, info);
    if (!waiter)
        return named(waiter.error());
    auto result = parse(file, *waiter, options);
    if (!result)
        return named(result.error());
    return result;
}

Outcome<std::unique_ptr<ChartRecording>> ChartCsvReader::readFile(const QString &path,
                                                                  const Options &options) {
    return assembled(readFileData(path, options));
}

} // namespace tipscope::model
