#include "benchsupport.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFile>
#include <QList>
#include <QProcess>
#include <QSysInfo>
#include <QTextStream>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <sys/resource.h>
#include <unistd.h>

namespace tipscope::bench {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;

QTextStream &out() {
    static QTextStream s(stdout);
    return s;
}

QTextStream &err() {
    static QTextStream s(stderr);
    return s;
}

QString cpuModel() {
    QFile f(QStringLiteral("/proc/cpuinfo"));
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return QStringLiteral("unknown");
    for (QByteArray line = f.readLine(); !line.isEmpty(); line = f.readLine()) {
        if (line.startsWith("model name"))
            return QString::fromLatin1(line.mid(line.indexOf(':') + 1)).trimmed();
    }
    return QStringLiteral("unknown");
}

qint64 timevalUs(const timeval &tv) {
    return qint64(tv.tv_sec) * 1'000'000 + tv.tv_usec;
}

} // namespace

void printFigure(const QString &name, double value, const QString &unit, int decimals) {
    out() << name << ": " << QString::number(value, 'f', decimals) << ' ' << unit << Qt::endl;
}

void printText(const QString &name, const QString &value) {
    out() << name << ": " << value << Qt::endl;
}

void printError(const QString &message) {
    out().flush();
    err() << "tipscope-bench: error: " << message << Qt::endl;
}

void printNote(const QString &message) {
    out().flush();
    err() << "tipscope-bench: " << message << Qt::endl;
}

void printMachineContext() {
    printFigure(QStringLiteral("bench.cores"), QThread::idealThreadCount(), QStringLiteral("cores"),
                0);
    printText(QStringLiteral("bench.cpu"), cpuModel());
    const QString build = QStringLiteral(TIPSCOPE_BUILD_TYPE);
    printText(QStringLiteral("bench.build"),
              build.isEmpty() ? QStringLiteral("unspecified") : build);
    printText(QStringLiteral("bench.qt"), QString::fromLatin1(qVersion()));
    printText(QStringLiteral("bench.kernel"), QSysInfo::kernelVersion());
}

qint64 selfCpuUs() {
    rusage ru{};
    ::getrusage(RUSAGE_SELF, &ru);
    return timevalUs(ru.ru_utime) + timevalUs(ru.ru_stime);
}

std::optional<qint64> processCpuUs(qint64 pid) {
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (pid <= 0 || !f.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QByteArray stat = f.readAll();
    // The command name in field 2 may hold spaces; the fields after its ')' are fixed.
    const QList<QByteArray> fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
    constexpr int kUtime = 11; // field 14 of proc(5), counted from field 3
    constexpr int kStime = 12;
    if (fields.size() <= kStime)
        return std::nullopt;
    const long ticksPerSecond = ::sysconf(_SC_CLK_TCK);
    const qint64 ticks = fields[kUtime].toLongLong() + fields[kStime].toLongLong();
    return ticks * 1'000'000 / qMax(1L, ticksPerSecond);
}

QString optionValue(const QStringList &args, const char *name, const QString &fallback) {
    const qsizetype i = args.indexOf(QLatin1String(name));
    return i >= 0 ? args.value(i + 1, fallback) : fallback;
}

namespace {

// The value of `--name` if it is given and within [min, max]; otherwise nullopt, with one error
// line when it was given.
template <typename T>
std::optional<T> checkedOption(const QStringList &args, const char *name, T fallback, T min, T max,
                               const char *what, std::optional<T> (*parse)(const QString &)) {
    const qsizetype i = args.indexOf(QLatin1String(name));
    if (i < 0)
        return fallback;
    const QString text = args.value(i + 1);
    if (const std::optional<T> v = parse(text); v && *v >= min && *v <= max)
        return v;
    printError(QStringLiteral("%1 takes %2 from %3 to %4, not '%5'")
                   .arg(QLatin1String(name), QLatin1String(what))
                   .arg(min)
                   .arg(max)
                   .arg(text.left(40)));
    return std::nullopt;
}

std::optional<double> parseFinite(const QString &text) {
    bool ok = false;
    const double v = text.toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

std::optional<qint64> parseWhole(const QString &text) {
    bool ok = false;
    const qint64 v = text.toLongLong(&ok);
    return ok ? std::optional<qint64>(v) : std::nullopt;
}

} // namespace

std::optional<double> numberOption(const QStringList &args, const char *name, double fallback,
                                   double min, double max) {
    return checkedOption(args, name, fallback, min, max, "a number", parseFinite);
}

std::optional<qint64> wholeOption(const QStringList &args, const char *name, qint64 fallback,
                                  qint64 min, qint64 max) {
    return checkedOption(args, name, fallback, min, max, "a whole number", parseWhole);
}

qint64 selfStatusBytes(const char *field) {
    QFile f(QStringLiteral("/proc/self/status"));
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return -1;
    for (QByteArray line = f.readLine(); !line.isEmpty(); line = f.readLine())
        if (line.startsWith(field))
            return line.mid(qstrlen(field)).trimmed().split(' ').first().toLongLong() * 1024;
    return -1;
}

void waitMs(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

bool runUntil(const std::function<bool()> &done, int timeoutMs) {
    QEventLoop loop;
    QTimer check;
    QObject::connect(&check, &QTimer::timeout, &loop, [&] {
        if (done() || interrupted())
            loop.quit();
    });
    check.start(100);
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    if (!done() && !interrupted())
        loop.exec();
    return done();
}

void stopOnSignals() {
    struct sigaction action {};
    action.sa_handler = [](int) { g_interrupted = 1; };
    ::sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
}

bool interrupted() {
    return g_interrupted != 0;
}

double quantile(QList<double> values, double p) {
    if (values.isEmpty())
        return 0;
    std::sort(values.begin(), values.end());
    const auto rank = qsizetype(std::ceil(p * double(values.size())));
    return values[std::clamp<qsizetype>(rank - 1, 0, values.size() - 1)];
}

double pacedWireLimitTxPerS(qint64 answered, qint64 bytes) {
    return answered > 0 && bytes > 0 ? kWireBytesPerSecond * double(answered) / double(bytes) : 0;
}

BusyLoad::BusyLoad(int count) {
    for (int i = 0; i < count; ++i) {
        // A detached shell outlives a bench that dies without its destructor: the loop asks
        // after the bench between its rounds and ends once it is gone.
        qint64 pid = 0;
        if (QProcess::startDetached(
                QStringLiteral("/bin/sh"),
                {QStringLiteral("-c"), QStringLiteral("p=%1; while kill -0 $p 2>/dev/null; do "
                                                      "i=0; while [ $i -lt 100000 ]; do "
                                                      "i=$((i+1)); done; done")
                                           .arg(QCoreApplication::applicationPid())},
                QString(), &pid))
            m_pids.push_back(pid);
    }
}

BusyLoad::~BusyLoad() {
    for (qint64 pid : m_pids)
        ::kill(pid_t(pid), SIGKILL);
}

} // namespace tipscope::bench
