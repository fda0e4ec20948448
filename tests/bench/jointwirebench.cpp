#include "jointwirebench.h"

#include "benchsupport.h"
#include "link/line.h"
#include "link/simtransport.h"
#include "model/appsettings.h"
#include "model/joints/jointwatcher.h"
#include "model/pollscheduler.h"
#include "model/stationmodel.h"
#include "model/telemetry/telemetry.h"
#include "model/telemetryrecorder.h"
#include "sim/simline.h"

#include <QDateTime>
#include <QEventLoop>
#include <QTimer>
#include <map>
#include <memory>

namespace tipscope::bench {

using namespace tipscope::model;

namespace {
constexpr int kBaud = 19200;
constexpr int kChunkMs = 8;
constexpr qint64 kMatchMs = 1000;

struct Options {
    double minutes = 10;
    double perMinute = 12;
    quint32 seed = 1;
    int liveMs = AppSettings{}.liveMs;
    int statusMs = AppSettings{}.statusMs;
};

struct Figure {
    QString name;
    double value;
    QString unit;
    int decimals;
};

// One simulated station on its own paced line, polled and watched as a session does.
class WireRun {
public:
    WireRun(const Options &o, bool adaptive)
        : m_recorder(m_telemetry, [] { return QDateTime::currentMSecsSinceEpoch(); })
        , m_watcher(m_telemetry) {
        m_sim.addDevice(std::make_unique<sim::SimStation>(QStringLiteral("DME"), 1));
        m_sim.setBaud(kBaud);
        m_sim.setChunkMs(kChunkMs);
        m_sim.setRandomJoints(o.perMinute, o.seed);
        QObject::connect(&m_sim, &sim::SimLine::jointMade,
                         [this](const sim::SimJoint &j) { m_truth.append(j); });
        link::LineSettings settings;
        settings.kind = link::LineSettings::Kind::Demo;
        m_line =
            std::make_unique<link::Line>(std::make_unique<link::SimTransport>(m_sim), settings);
        const sim::SimDevice &d = *m_sim.devices().first();
        link::DeviceInfo info;
        info.address = d.address();
        info.model = d.modelName();
        info.family = d.family().name;
        info.softwareVersion = d.softwareVersion();
        m_station = std::make_unique<StationModel>(m_line->queue(), info);
        m_recorder.watch(m_station.get());
        StationModel *station = m_station.get();
        m_watcher.watch(station,
                        [station](int port) { return TelemetryRecorder::keyOf(*station, port); });
        QObject::connect(&m_watcher, &JointWatcher::jointEnded,
                         [this](const JointRecord &j) { m_found.append(j); });
        m_scheduler.addDevice(station);
        m_scheduler.setVisiblePorts(station, {1, 2, 3, 4});
        m_scheduler.setInterval(PollClass::Live, o.liveMs);
        m_scheduler.setInterval(PollClass::Status, o.statusMs);
        m_scheduler.setAdaptive(adaptive);
    }

    void start() {
        m_line->open();
        m_sim.setClockRunning(true);
        m_scheduler.start();
        m_startMs = QDateTime::currentMSecsSinceEpoch();
    }

    void stop() {
        m_scheduler.stop();
        m_endMs = QDateTime::currentMSecsSinceEpoch();
    }

    [[nodiscard]] QList<Figure> figures() const;

private:
    [[nodiscard]] QList<double> tipPeriods() const;

    sim::SimLine m_sim;
    std::unique_ptr<link::Line> m_line;
    std::unique_ptr<StationModel> m_station;
    Telemetry m_telemetry;
    TelemetryRecorder m_recorder;
    JointWatcher m_watcher;
    PollScheduler m_scheduler;
    QList<sim::SimJoint> m_truth;
    QList<JointRecord> m_found;
    qint64 m_startMs = 0;
    qint64 m_endMs = 0;
};

QList<double> WireRun::tipPeriods() const {
    QList<double> periods;
    for (int port = 1; port <= 4; ++port) {
        const TelemetryBuffer *b = m_telemetry.buffer(TelemetryRecorder::keyOf(*m_station, port));
        if (!b || b->isEmpty())
            continue;
        const auto tips =
            b->samples(b->seriesIndex(QStringLiteral("tip")), b->firstTime(), b->lastTime() + 1);
        for (qsizetype i = 1; i < tips.size(); ++i)
            periods.append(double(tips.at(i).timeMs - tips.at(i - 1).timeMs));
    }
    return periods;
}

// Joints that ended before the run did, matched one to one by port and start.
QList<Figure> WireRun::figures() const {
    const qint64 cutoff = m_endMs - kMatchMs;
    QList<sim::SimJoint> truth;
    for (const sim::SimJoint &t : m_truth)
        if (t.startMs + t.recoveryMs < cutoff)
            truth.append(t);
    QList<JointRecord> found;
    for (const JointRecord &j : m_found)
        if (j.startMs + j.recoveryMs.value_or(j.durationMs) < cutoff)
            found.append(j);
    QList<bool> used(truth.size(), false);
    QList<double> recoveryErrors, startErrors;
    double signedSum = 0; // measured minus true: a bias shows here
    int matched = 0;
    for (const JointRecord &j : std::as_const(found)) {
        for (qsizetype k = 0; k < truth.size(); ++k) {
            const sim::SimJoint &t = truth.at(k);
            if (used.at(k) || t.port != j.port || qAbs(t.startMs - j.startMs) > kMatchMs)
                continue;
            used[k] = true;
            ++matched;
            startErrors.append(double(qAbs(j.startMs - t.startMs)));
            if (j.recoveryMs) {
                recoveryErrors.append(double(qAbs(*j.recoveryMs - t.recoveryMs)));
                signedSum += double(*j.recoveryMs - t.recoveryMs);
            }
            break;
        }
    }
    // What was missed, on standard error, for whoever looks into the recall.
    for (qsizetype k = 0; k < truth.size(); ++k) {
        if (used.at(k))
            continue;
        const sim::SimJoint &t = truth.at(k);
        QString near;
        for (const JointRecord &j : std::as_const(found))
            if (j.port == t.port && qAbs(j.startMs - t.startMs) < 10'000)
                near += QStringLiteral(" [found %1 ms %2]")
                            .arg(j.startMs - t.startMs)
                            .arg(jointVerdictName(j.verdict));
        qWarning("missed: port %d, %lld ms into the run, %d K, recovery %lld ms;%s", t.port,
                 t.startMs - m_startMs, t.depthK, t.recoveryMs, qPrintable(near));
    }
    const double seconds = double(m_endMs - m_startMs) / 1000;
    const QList<double> periods = tipPeriods();
    const QString ms = QStringLiteral("ms");
    return {
        {QStringLiteral("true"), double(truth.size()), QStringLiteral("joints"), 0},
        {QStringLiteral("found"), double(found.size()), QStringLiteral("joints"), 0},
        {QStringLiteral("precision"), found.isEmpty() ? 0 : double(matched) / double(found.size()),
         QString(), 4},
        {QStringLiteral("recall"), truth.isEmpty() ? 0 : double(matched) / double(truth.size()),
         QString(), 4},
        {QStringLiteral("recovery_error_p50"), quantile(recoveryErrors, 0.5), ms, 0},
        {QStringLiteral("recovery_error_p95"), quantile(recoveryErrors, 0.95), ms, 0},
        {QStringLiteral("recovery_error_max"), quantile(recoveryErrors, 1.0), ms, 0},
        {QStringLiteral("recovery_bias"),
         recoveryErrors.isEmpty() ? 0 : signedSum / double(recoveryErrors.size()), ms, 0},
        {QStringLiteral("start_error_p95"), quantile(startErrors, 0.95), ms, 0},
        {QStringLiteral("tip_period_p50"), quantile(periods, 0.5), ms, 0},
        {QStringLiteral("tip_period_p95"), quantile(periods, 0.95), ms, 0},
        {QStringLiteral("polls_per_s"), seconds > 0 ? double(m_scheduler.pollsDone()) / seconds : 0,
         QStringLiteral("polls/s"), 1},
    };
}

Options parse(const QStringList &args) {
    Options o;
    for (qsizetype i = 0; i + 1 < args.size(); ++i) {
        const QString &a = args.at(i);
        const QString &v = args.at(i + 1);
        if (a == QLatin1String("--minutes"))
            o.minutes = qMax(0.1, v.toDouble());
        else if (a == QLatin1String("--per-minute"))
            o.perMinute = qBound(1.0, v.toDouble(), 60.0);
        else if (a == QLatin1String("--seed"))
            o.seed = v.toUInt();
        else if (a == QLatin1String("--live-ms"))
            o.liveMs = qMax(10, v.toInt());
        else if (a == QLatin1String("--status-ms"))
            o.statusMs = qMax(10, v.toInt());
    }
    return o;
}
} // namespace

int runJointWireBench(const QStringList &args) {
    const Options o = parse(args);
    printText(QStringLiteral("joints.wire.station"), QStringLiteral("DME, 4 ports"));
    printFigure(QStringLiteral("joints.wire.baud"), kBaud, QStringLiteral("baud"), 0);
    printFigure(QStringLiteral("joints.wire.minutes"), o.minutes, QStringLiteral("min"), 1);
    printFigure(QStringLiteral("joints.wire.per_minute"), o.perMinute,
                QStringLiteral("joints/min/port"), 1);
    printFigure(QStringLiteral("joints.wire.live_ms"), o.liveMs, QStringLiteral("ms"), 0);
    printFigure(QStringLiteral("joints.wire.status_ms"), o.statusMs, QStringLiteral("ms"), 0);
    WireRun adaptive(o, true);
    WireRun fixed(o, false);
    adaptive.start();
    fixed.start();
    QEventLoop loop;
    QTimer::singleShot(qint64(o.minutes * 60'000), &loop, &QEventLoop::quit);
    loop.exec();
    adaptive.stop();
    fixed.stop();
    // Side by side: each figure with adaptive sampling, then the same without.
    const QList<Figure> on = adaptive.figures();
    const QList<Figure> off = fixed.figures();
    for (qsizetype i = 0; i < on.size(); ++i) {
        const Figure &a = on.at(i);
        const Figure &b = off.at(i);
        printFigure(QStringLiteral("joints.wire.") + a.name, a.value, a.unit, a.decimals);
        printFigure(QStringLiteral("joints.wire.adaptive_off.") + b.name, b.value, b.unit,
                    b.decimals);
    }
    return 0;
}

} // namespace tipscope::bench
