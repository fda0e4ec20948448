#include "replaybench.h"

#include "benchsupport.h"

#include "model/recording/chartcsvreader.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <functional>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace tipscope::bench {

using model::ChartCsvReader;

namespace {

constexpr qint64 kT0 = 1'700'000'000'000;
constexpr qint64 kMB = 1 << 20;

// Lets the peak resident set (VmHWM) start again from the current one (Linux 4.0 and later).
void resetPeak() {
#ifdef __GLIBC__
    malloc_trim(0); // what the last file freed goes back to the system first
#endif
    QFile f(QStringLiteral("/proc/self/clear_refs"));
    if (f.open(QIODevice::WriteOnly))
        f.write("5");
}

// chartcsv::timeText() without QDateTime, whose formatting would make writing the files (and
// feeding the FIFO) slower than reading them.
QByteArray timeText(qint64 ms) {
    const qint64 days = ms / 86'400'000;
    qint64 rest = ms % 86'400'000;
    // Civil date from days since 1970-01-01 (H. Hinnant's algorithm).
    const qint64 z = days + 719468;
    const qint64 era = z / 146097;
    const qint64 doe = z - era * 146097;
    const qint64 yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const qint64 doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const qint64 mp = (5 * doy + 2) / 153;
    const qint64 d = doy - (153 * mp + 2) / 5 + 1;
    const qint64 m = mp < 10 ? mp + 3 : mp - 9;
    const qint64 y = yoe + era * 400 + (m <= 2);
    char text[128];
    const qint64 h = rest / 3'600'000, mi = rest / 60'000 % 60, sec = rest / 1000 % 60;
    rest %= 1000;
    std::snprintf(text, sizeof text, "%04lld-%02lld-%02lldT%02lld:%02lld:%02lld.%03lldZ", y, m, d,
                  h, mi, sec, rest);
    return QByteArray(text);
}

// Writes rows from `row(i)` until the file holds `bytes`.
bool writeFile(const QString &path, const QByteArray &head, qint64 bytes,
               const std::function<QByteArray(qint64)> &row) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    QByteArray chunk = head;
    qint64 written = 0;
    for (qint64 i = 0; written + chunk.size() < bytes; ++i) {
        chunk += row(i);
        if (chunk.size() > kMB) {
            written += f.write(chunk);
            chunk.clear();
        }
    }
    return f.write(chunk) >= 0 && f.flush();
}

QByteArray stationHead() {
    QByteArray h = "# TipScope chart data, format 1\n# software: TipScope bench\ntime";
    for (int p = 1; p <= 4; ++p)
        for (const char *s : {"tip [°C]", "setpoint [°C]", "power [%]", "status", "transistor [°C]",
                              "transformer [°C]"})
            h += ",port" + QByteArray::number(p) + ' ' + s;
    return h + ",feeder fed [mm],feeder speed [mm/s],feeder feeding,events\n";
}

// A row of one channel at a time, as the Charts page records four ports polled in turn and a
// feeder; the values move a little so they are not all alike.
QByteArray stationRow(qint64 i, bool event) {
    const int channel = int(i % 5);
    QByteArray row = timeText(kT0 + i * 50);
    for (int c = 0; c < 5; ++c) {
        if (c != channel) {
            row += c < 4 ? ",,,,,," : ",,,";
        } else if (c < 4) {
            row += ',' + QByteArray::number(340 + i % 17) + ",350," +
                   QByteArray::number(i % 1000 / 10) + '.' + QByteArray::number(i % 10) +
                   ",0,45,38";
        } else {
            row += ',' + QByteArray::number(i / 5 % 100000) + ".5,10.0," +
                   QByteArray::number(i / 100 % 2);
        }
    }
    return row + (event ? ",port1 status: Working \xe2\x86\x92 Stand\n" : ",\n");
}

struct Result {
    qint64 fileBytes = 0;
    qint64 readBytes = 0;
    double seconds = 0;
    qint64 peakAbove = 0;
    qint64 held = 0;
    QString text;
};

Result readAndMeasure(const QString &path, qint64 fileBytes) {
    Result r;
    r.fileBytes = fileBytes;
    resetPeak();
    const qint64 before = selfStatusBytes("VmRSS:");
    ChartCsvReader::Options options;
    options.progress = [&r](qint64 bytes) {
        r.readBytes = bytes;
        return true;
    };
    QElapsedTimer clock;
    clock.start();
    const auto read = ChartCsvReader::readFile(path, options);
    r.seconds = double(clock.nsecsElapsed()) / 1e9;
    r.peakAbove = selfStatusBytes("VmHWM:") - before;
    if (read) {
        const model::ChartRecording *recording = read->get();
        r.held = recording->memoryBytes();
        r.text = QStringLiteral("replayed %1 rows, %2 events")
                     .arg(recording->rows)
                     .arg(recording->events.size());
    } else {
        r.text = QStringLiteral("refused: ") + read.error();
    }
    if (r.fileBytes == 0)
        r.fileBytes = r.readBytes;
    return r;
}

void print(const QString &name, const Result &r) {
    const QString p = QStringLiteral("replay.") + name + QLatin1Char('.');
    const double fileMb = double(r.fileBytes) / kMB;
    printFigure(p + QStringLiteral("file_mb"), fileMb, QStringLiteral("MB"));
    printFigure(p + QStringLiteral("seconds"), r.seconds, QStringLiteral("s"), 2);
    printFigure(p + QStringLiteral("mb_per_s"), double(r.readBytes) / kMB / r.seconds,
                QStringLiteral("MB/s"));
    printFigure(p + QStringLiteral("read_mb"), double(r.readBytes) / kMB, QStringLiteral("MB"));
    printFigure(p + QStringLiteral("peak_rss_ratio"), double(r.peakAbove) / double(r.fileBytes),
                QStringLiteral("x"), 3);
    printFigure(p + QStringLiteral("held_ratio"), double(r.held) / double(r.fileBytes),
                QStringLiteral("x"), 3);
    printText(p + QStringLiteral("result"), r.text.left(160));
}

// Rows through a FIFO until the reader stops reading: what the limit on bytes read is for.
Result readFifo(const QString &path) {
    ::signal(SIGPIPE, SIG_IGN);
    if (::mkfifo(QFile::encodeName(path).constData(), 0600) != 0)
        return {0, 0, 0,
                0, 0, QStringLiteral("no FIFO: ") + QString::fromLocal8Bit(strerror(errno))};
    std::atomic<qint64> written{0};
    std::thread writer([&] {
        const int fd = ::open(QFile::encodeName(path).constData(), O_WRONLY);
        if (fd < 0)
            return;
        QByteArray chunk = stationHead();
        // Rows padded with spaces (cells are trimmed): the byte limit comes before the limit of
        // samples per channel.
        const QByteArray padding(240, ' ');
        for (qint64 i = 0;; ++i) {
            QByteArray row = stationRow(i, i % 300 == 0);
            chunk += row.insert(25, padding);
            if (chunk.size() < kMB)
                continue;
            if (::write(fd, chunk.constData(), size_t(chunk.size())) != chunk.size())
                break; // the reader closed its end
            written += chunk.size();
            chunk.clear();
        }
        ::close(fd);
    });
    Result r = readAndMeasure(path, 0);
    writer.join();
    return r;
}

} // namespace

int runReplayBench(const QStringList &args) {
    if (args.contains(QStringLiteral("--help")) || args.contains(QStringLiteral("-h"))) {
        printNote(QStringLiteral("replay [--mb MB] [--no-fifo]: read speed and memory of replay"));
        return 0;
    }
    const std::optional<qint64> mbOption = wholeOption(args, "--mb", 200, 1, 1000);
    if (!mbOption)
        return 2;
    const qint64 mb = *mbOption;
    QTemporaryDir dir;
    if (!dir.isValid()) {
        printError(QStringLiteral("no temporary folder"));
        return 1;
    }
    const auto file = [&dir](const char *name) { return dir.filePath(QLatin1String(name)); };

    QList<std::pair<QString, std::function<bool(const QString &)>>> files = {
        {QStringLiteral("samples"),
         [mb](const QString &p) {
             return writeFile(p, stationHead(), mb * kMB,
                              [](qint64 i) { return stationRow(i, i % 300 == 0); });
         }},
        {QStringLiteral("events"),
         [mb](const QString &p) {
             return writeFile(p, stationHead(), mb * kMB / 5,
                              [](qint64 i) { return stationRow(i, true); });
         }},
        {QStringLiteral("comments"),
         [](const QString &p) {
             return writeFile(p, "# TipScope chart data, format 1\n", 84 * kMB, [](qint64 i) {
                 return "# channel port" + QByteArray::number(i) +
                        ": device=DME-4C; address=01; device software=9996780; port=1; "
                        "tool=T245\n";
             });
         }},
        {QStringLiteral("dense"),
         [mb](const QString &p) {
             QByteArray head = "time", cells;
             for (int c = 1; c <= 255; ++c) {
                 head += ",port" + QByteArray::number(c) + " tip [°C]";
                 cells += ",1";
             }
             return writeFile(p, head + '\n', mb * kMB / 4, [&cells](qint64 i) {
                 return timeText(kT0 + i * 100) + cells + '\n';
             });
         }},
    };
    for (const auto &[name, write] : files) {
        const QString path = file(name.toLatin1().constData());
        if (!write(path)) {
            printError(QStringLiteral("cannot write %1").arg(path));
            return 1;
        }
        print(name, readAndMeasure(path, QFileInfo(path).size()));
        QFile::remove(path);
    }
    if (!args.contains(QStringLiteral("--no-fifo")))
        print(QStringLiteral("fifo"), readFifo(file("fifo.csv")));
    return 0;
}

} // namespace tipscope::bench
