// tipscope-cli record FILE [--duration S]: the Charts page's continuous recording without a
// window. The same session (every port's live values polled as when the Charts page is shown),
// the same recorder and CSV writer, so the file replays in the application and measures with
// `tipscope-cli measure`. Recording starts once every channel has its first sample and the alarm
// limits are read (so the header names the tools and limits, as the page's would), and ends
// after S seconds, or on Ctrl-C or SIGTERM, with the file complete.
#include "clicommands.h"
#include "clistop.h"

#include "model/chart/chartseries.h"
#include "model/recording/chartrecorder.h"
#include "model/session.h"

#include <QDeadlineTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QTimer>
#include <cmath>
#include <limits>

namespace tipscope::cli {

using namespace tipscope::model;

namespace {

struct CliRecordTr {
    Q_DECLARE_TR_FUNCTIONS(CliRecord)
};

constexpr int kFirstSamplesMs = 30'000;
constexpr int kLimitsMs = 10'000;

// Runs the event loop until `done` holds, `timeoutMs` passed, or a stop was asked for.
template <class Done> bool waitFor(Done done, int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    QEventLoop loop;
    QTimer check;
    QObject::connect(&check, &QTimer::timeout, &loop, [&] {
        if (done() || deadline.hasExpired() || stopRequested())
            loop.quit();
    });
    check.start(kStopCheckMs);
    if (!done())
        loop.exec();
    return done();
}

// kOk once the devices are found, or the exit code after saying why not.
int connect(Session &session, QTextStream &err) {
    const auto settled = [&session] {
        const Session::State s = session.state();
        return s == Session::State::Connected || s == Session::State::Retrying ||
               s == Session::State::Failed;
    };
    waitFor(settled, std::numeric_limits<int>::max());
    if (stopRequested()) {
        err << CliRecordTr::tr("tipscope-cli: interrupted before the recording started")
            << Qt::endl;
        return kUsage;
    }
    if (session.state() != Session::State::Connected) {
        link::Line *line = session.line();
        err << CliRecordTr::tr("tipscope-cli: cannot open %1: %2")
                   .arg(line ? line->transport().description() : QString(),
                        line ? line->lastError() : session.stateText())
            << Qt::endl;
        return kTransport;
    }
    if (session.devices().isEmpty()) {
        err << "tipscope-cli: " << session.stateText() << Qt::endl;
        return kNoAnswer;
    }
    return kOk;
}

bool everyChannelSampled(Session &session) {
    for (const ChartChannel &c : sessionChannels(session)) {
        const TelemetryBuffer *b = session.telemetry().buffer(c.key);
        if (!b || b->isEmpty())
            return false;
    }
    return true;
}

// The header names each port's alarm limits as read: wait a little for them (settings are read
// after the live values; a family without limits never has them).
bool everyLimitRead(Session &session) {
    for (const ChartChannel &c : sessionChannels(session))
        if (!c.isFeeder() && (!c.highAlarm || !c.lowAlarm))
            return false;
    return true;
}

} // namespace

int runRecord(const CliOptions &o, QTextStream &out, QTextStream &err) {
    if (o.args.size() != 1) {
        err << CliRecordTr::tr(
                   "tipscope-cli: record takes one FILE, e.g. record line3.csv --duration 60")
            << Qt::endl;
        return kUsage;
    }
    bool ok = true;
    const double durationS =
        o.values.value(QStringLiteral("duration"), QStringLiteral("0")).toDouble(&ok);
    if (!ok || !std::isfinite(durationS) || durationS < 0 || durationS > 1e9) {
        err << CliRecordTr::tr("tipscope-cli: --duration takes seconds (0: until interrupted)")
            << Qt::endl;
        return kUsage;
    }
    // Said before connecting, which may take long: the file is only created once samples come.
    const QFileInfo file(o.args.first());
    const QFileInfo folder(file.absolutePath());
    if (!folder.isDir() || !folder.isWritable() || (file.exists() && !file.isWritable())) {
        err << CliRecordTr::tr("tipscope-cli: cannot record to %1: %2")
                   .arg(file.filePath(), !folder.isDir() ? CliRecordTr::tr("no such folder")
                                                         : CliRecordTr::tr("not writable"))
            << Qt::endl;
        return kUsage;
    }
    catchStopSignals();

    Session session;
    session.connectTo(sessionSettingsOf(o));
    if (const int rc = connect(session, err); rc != kOk)
        return rc;
    if (StationModel *station = session.station()) {
        QSet<int> ports; // all of them, as the Charts page polls them
        for (PortModel *p : station->ports())
            ports.insert(p->number());
        session.scheduler().setVisiblePorts(station, ports);
    }
    waitFor([&session] { return everyChannelSampled(session); }, kFirstSamplesMs);
    waitFor([&session] { return everyLimitRead(session); }, kLimitsMs);

    const QString path = o.args.first();
    const QList<ChartChannel> channels = sessionChannels(session);
    ChartRecorder recorder(session.telemetry());
    const QString error = recorder.start(path, channels, TemperatureUnit::Celsius,
                                         QCoreApplication::applicationVersion());
    if (!error.isEmpty()) {
        err << CliRecordTr::tr("tipscope-cli: cannot record to %1: %2").arg(path, error)
            << Qt::endl;
        return kUsage;
    }
    QString failure;
    QObject::connect(&recorder, &ChartRecorder::failed, &recorder,
                     [&failure](const QString &why) { failure = why; });
    QObject::connect(&session.eventLog(), &EventLog::appended, &recorder,
                     [&recorder, &channels](const Event &e) {
                         if (const auto marked = ChartEvent::fromLog(e, channels))
                             recorder.addEvent(*marked);
                     });
    // As monitor does: a lost line is said, and so is its return.
    QObject::connect(&session, &Session::stateChanged, &recorder,
                     [&err](Session::State state, const QString &text) {
                         if (state == Session::State::Retrying ||
                             state == Session::State::Connected)
                             err << "# " << text << Qt::endl;
                     });
    QStringList names;
    for (const ChartChannel &c : channels)
        names.append(c.id);
    err << CliRecordTr::tr("# recording %1 of %2 to %3")
               .arg(names.join(QStringLiteral(", ")), session.stateText(), path)
        << Qt::endl;
    const int durationMs = durationS > 0 ? int(qMin(durationS * 1000, 2e9)) : -1;
    waitFor([&failure] { return !failure.isEmpty(); },
            durationMs < 0 ? std::numeric_limits<int>::max() : durationMs);
    recorder.stop();
    if (!failure.isEmpty()) {
        err << CliRecordTr::tr("tipscope-cli: writing %1 failed: %2").arg(path, failure)
            << Qt::endl;
        return kUsage;
    }
    const qint64 rows = recorder.rowsWritten();
    out << CliRecordTr::tr("recorded %n row(s) to %1", nullptr,
                           int(qMin<qint64>(rows, 1'000'000'000)))
               .arg(path)
        << Qt::endl;
    return kOk;
}

} // namespace tipscope::cli
