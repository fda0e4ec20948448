#include "simstations.h"

#include "benchsupport.h"
#include "ptyfixtures.h"

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <csignal>

namespace tipscope::bench {

DetachedSim::~DetachedSim() {
    if (m_pid > 0)
        ::kill(pid_t(m_pid), SIGTERM);
}

QString DetachedSim::start(const QStringList &args, QString *error) {
    const QString out = m_dir.filePath(QStringLiteral("out"));
    QProcess process;
    process.setProgram(testing::binaryPath(QStringLiteral("tipscope-sim")));
    process.setArguments(args);
    process.setStandardOutputFile(out);
    process.setStandardErrorFile(m_dir.filePath(QStringLiteral("err")));
    if (!m_dir.isValid() || !process.startDetached(&m_pid)) {
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
