#include "simstations.h"

#include "benchsupport.h"
#include "ptyfixtures.h"

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace tipscope::bench {

DetachedSim::~DetachedSim() {
    if (m_pid > 0)
        ::kill(pid_t(m_pid), SIGTERM);
    if (m_control >= 0)
        ::close(m_control);
}

QString DetachedSim::start(const QStringList &args, QString *error) {
    const QString out = m_dir.filePath(QStringLiteral("out"));
    const QByteArray control = QFile::encodeName(m_dir.filePath(QStringLiteral("control")));
    // Opened for reading and writing here, the FIFO neither blocks the simulator's open of its
    // standard input nor ever gives it an end of input.
    if (!m_dir.isValid() || ::mkfifo(control.constData(), 0600) != 0 ||
        (m_control = ::open(control.constData(), O_RDWR | O_CLOEXEC)) < 0) {
        *error = QStringLiteral("no control FIFO for tipscope-sim");
        return {};
    }
    QProcess process;
    process.setProgram(testing::binaryPath(QStringLiteral("tipscope-sim")));
    process.setArguments(args);
    process.setStandardInputFile(QFile::decodeName(control));
    process.setStandardOutputFile(out);
    process.setStandardErrorFile(m_dir.filePath(QStringLiteral("err")));
    if (!process.startDetached(&m_pid)) {
        *error = QStringLiteral("tipscope-sim did not start");
        return {};
    }
    QFile file(out);
    QElapsedTimer waited;
    waited.start();
    while (waited.elapsed() < 10000) {
        if (file.open(QIODevice::ReadOnly | QIODevice::Text)) {
            const QByteArray first = file.readLine();
            file.close();
            if (first.endsWith('\n'))
                return QString::fromLocal8Bit(first).trimmed();
        }
        waitMs(50);
    }
    *error = QStringLiteral("tipscope-sim printed no address");
    return {};
}

QString DetachedSim::errorText() const {
    QFile file(m_dir.filePath(QStringLiteral("err")));
    return file.open(QIODevice::ReadOnly) ? QString::fromLocal8Bit(file.readAll()) : QString();
}

std::optional<qint64> DetachedSim::answers() {
    static const QRegularExpression answered(
        QStringLiteral("^requests \\d+ writes \\d+ answers (\\d+) dropped"),
        QRegularExpression::MultilineOption);
    QFile file(m_dir.filePath(QStringLiteral("out")));
    if (m_control < 0 || !file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const qint64 seen = file.size(); // the reply comes after what is there now
    if (::write(m_control, "stats\n", 6) != 6)
        return std::nullopt;
    QElapsedTimer waited;
    waited.start();
    while (waited.elapsed() < 1000) {
        file.seek(seen);
        const QRegularExpressionMatch m = answered.match(QString::fromLocal8Bit(file.readAll()));
        if (m.hasMatch())
            return m.captured(1).toLongLong();
        waitMs(5);
    }
    return std::nullopt;
}

std::optional<qint64> answersOf(const std::vector<SimStation> &stations) {
    qint64 sum = 0;
    for (const SimStation &s : stations) {
        const std::optional<qint64> n = s.sim->answers();
        if (!n)
            return std::nullopt;
        sum += *n;
    }
    return sum;
}

std::vector<SimStation> startSimStations(int stations,
                                         const std::function<QStringList(int)> &argsOf) {
    std::vector<SimStation> started;
    for (int i = 0; i < stations; ++i) {
        auto sim = std::make_unique<DetachedSim>(
            QStringLiteral("line%1").arg(i + 1, 2, 10, QLatin1Char('0')));
        QString error;
        const QString address = sim->start(argsOf(i), &error);
        if (address.isEmpty()) {
            printError(QStringLiteral("%1: %2").arg(sim->name(), error));
            return {};
        }
        started.push_back({std::move(sim), address});
    }
    return started;
}

QStringList plantStationArgs(int i, int jointsPerMinute, int pace, int chunkMs) {
    QStringList args{QStringLiteral("--model"),
                     QStringLiteral("DME"),
                     QStringLiteral("--tcp"),
                     QStringLiteral("127.0.0.1:0"),
                     QStringLiteral("--joints-per-minute"),
                     QString::number(jointsPerMinute),
                     QStringLiteral("--seed"),
                     QString::number(i + 1),
                     QStringLiteral("--pace"),
                     QString::number(pace),
                     QStringLiteral("--chunk"),
                     QString::number(chunkMs)};
    if (i % 2 == 1)
        args << QStringLiteral("--feeder");
    return args;
}

QString lastLines(const QString &log, int count) {
    const QStringList lines = log.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    return lines.mid(qMax(0, int(lines.size()) - count)).join(QLatin1Char('\n'));
}

} // namespace tipscope::bench
