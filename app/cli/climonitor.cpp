// tipscope-cli monitor: the line the options name, or every line of --workspace, through the line
// service every front end opens: the core's session polls it (adaptive sampling, the wire full
// while a joint lasts), its joint watcher finds the joints, judged by the shared joint limits
// (and --limit), and the journal keeps them with the work context in force. The monitor only
// prints what the models hold: every --interval each port's latest tip temperature, setpoint,
// power and status ("P1 --" while they are not current), a line per joint as it ends, and the
// rows of --csv. The interval decides what is printed and written, never what is read or how
// often. A lost line is said once and reconnects by itself. A workspace line that is a recording
// is played through the same path, and a monitor of recordings only ends once each is played.
#include "clicommands.h"

#include "climonitorcsv.h"
#include "clistop.h"

#include "base/elide.h"
#include "model/device/displayunits.h"
#include "model/device/portmodel.h"
#include "model/workspace/workspacefile.h"
#include "protocol/valuecodec.h"
#include "service/lineservice.h"

#include <QDateTime>
#include <QEventLoop>
#include <QFileInfo>
#include <QHash>
#include <QTimer>
#include <algorithm>
#include <cmath>

namespace tipscope::cli {

using namespace tipscope::model;

namespace {

struct CliMonitorTr {
    Q_DECLARE_TR_FUNCTIONS(CliMonitor)
};

constexpr int kFinishMs = 10'000;
// How long a line may take to open and find its station before a monitor of one line gives up.
constexpr int kFirstContactMs = 30'000;

// One line as the monitor prints it.
struct MonitoredLine {
    QString name;
    QString prefix; // "[cell-3] " in a workspace, nothing for one line
    Session *session = nullptr;
    std::shared_ptr<MonitorCsv> csv;
    QString csvPath;         // a file of its own, created once the line has a station
    bool csvFailed = false;  // the CSV could not be created or written: said once, then left
    QString describedDevice; // what the CSV last named
    bool lost = false;       // the loss was said; the return will be
    bool everConnected = false;
    bool lastCycleWhole = false; // every port current at the last print
};

QString valueText(const Parameter *p) {
    const auto v = p ? p->value() : std::nullopt;
    return v ? protocol::describeValue(p->spec(), *v, protocol::Wording::Catalog) : QString();
}

// A value is shown while it is current (read, on a line that is up); one the station refuses or
// has not answered is "?" and costs only itself.
bool isShown(const Parameter *p) {
    return p && p->isCurrent() && !p->isRefused();
}

// "P1 350/350 °C 5.0% working", or "P1 --" while the port's tip temperature is not current (the
// line is down, or not read yet). The fields of the CSV row are set while it is current; a field
// the station does not give is empty there.
QString portText(const PortModel &port, QString *csvFields) {
    const Parameter *tip = port.parameter(protocol::Role::TipTemperature);
    const Parameter *setpoint = port.parameter(protocol::Role::Setpoint);
    const Parameter *power = port.parameter(protocol::Role::Power);
    const Parameter *status = port.parameter(protocol::Role::Status);
    if (!isShown(tip))
        return CliMonitorTr::tr("P%1 --").arg(port.number());
    const QString setpointText = isShown(setpoint) ? valueText(setpoint) : QString();
    const QString powerText =
        isShown(power)
            ? QString::number(double(power->number().value_or(0)) *
                                  displayFormat(power->spec(), TemperatureUnit::Celsius).scale,
                              'f', 1)
            : QString();
    const QString statusText = isShown(status) ? valueText(status) : QString();
    *csvFields =
        QStringLiteral("%1,%2,%3,\"%4\"").arg(valueText(tip), setpointText, powerText, statusText);
    const auto orUnknown = [](const QString &text) {
        return text.isEmpty() ? QStringLiteral("?") : text;
    };
    return QStringLiteral("P%1 %2/%3 °C %4% %5")
        .arg(port.number())
        .arg(valueText(tip), orUnknown(setpointText), orUnknown(powerText), orUnknown(statusText));
}

// The CSV failed (it could not be created, or a row could not be written whole): said once; the
// monitor goes on printing and journaling, and ends non-zero.
void dropCsv(MonitoredLine &line, const QString &path, const QString &why, QTextStream &err) {
    if (!line.csvFailed)
        err << line.prefix << "# "
            << CliMonitorTr::tr(
                   "tipscope-cli: writing %1 failed: %2; monitoring goes on without it")
                   .arg(path, why)
            << Qt::endl;
    line.csvFailed = true;
    line.csv.reset();
}

void printCycle(MonitoredLine &line, QTextStream &out, QTextStream &err) {
    StationModel *station = line.session->station();
    if (!station)
        return;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const QString stamp = QDateTime::fromMSecsSinceEpoch(now).toString(Qt::ISODateWithMs);
    if (!line.csv && !line.csvPath.isEmpty() && !line.csvFailed) {
        auto created = MonitorCsv::create(line.csvPath, false);
        if (created)
            line.csv = created.value();
        else
            dropCsv(line, line.csvPath, created.error(), err);
    }
    if (line.csv && line.describedDevice != station->info().summary()) {
        line.describedDevice = station->info().summary();
        if (!line.csv->describe(line.name, line.describedDevice))
            dropCsv(line, line.csv->path(), line.csv->errorText(), err);
    }
    QStringList parts;
    bool whole = true;
    for (const PortModel *port : station->ports()) {
        QString fields;
        parts.append(portText(*port, &fields));
        whole = whole && !fields.isEmpty();
        if (line.csv && !fields.isEmpty() &&
            !line.csv->write(line.name, stamp, port->number(), fields))
            dropCsv(line, line.csv->path(), line.csv->errorText(), err);
    }
    line.lastCycleWhole = whole;
    out << line.prefix << stamp << "  " << parts.join(QLatin1String(" | ")) << Qt::endl;
}

// "2026-12-02T10:41:03.120  joint P1 C245 350 °C lowest 318 °C dip 32 K recovery 1.84 s ok"
QString jointLine(const JointRecord &j) {
    return QStringLiteral("%1  joint P%2 %3 %4 °C lowest %5 °C dip %6 K recovery %7 %8")
        .arg(QDateTime::fromMSecsSinceEpoch(j.startMs).toString(Qt::ISODateWithMs))
        .arg(j.port)
        .arg(j.tool.isEmpty() ? QStringLiteral("-") : j.tool)
        .arg(j.setpoint)
        .arg(QString::number(j.lowestTip, 'f', 1), QString::number(j.dipDepth, 'f', 1))
        .arg(recoveryWords(j))
        .arg(jointVerdictName(j.verdict));
}

// The line is lost and back: each said once, not at every retry.
void followLine(MonitoredLine &line, QTextStream &err) {
    QObject::connect(
        line.session, &Session::stateChanged, line.session,
        [&line, &err](Session::State state, const QString &text) {
            if (line.session->isPlayback()) {
                // A recording is played once: said when it is over, or why it cannot be.
                line.everConnected = line.everConnected || state == Session::State::Connected;
                if (state == Session::State::Disconnected || state == Session::State::Failed)
                    err << line.prefix << "# " << text << Qt::endl;
                return;
            }
            if (state == Session::State::Connected) {
                if (line.lost)
                    err << line.prefix << "# "
                        << CliMonitorTr::tr("reconnected to %1")
                               .arg(line.session->line()->transport().description())
                        << Qt::endl;
                line.lost = false;
                line.everConnected = true;
            } else if ((state == Session::State::Retrying || state == Session::State::Failed) &&
                       !line.lost) {
                line.lost = true;
                err << line.prefix << "# " << text << Qt::endl;
            }
        });
}

base::Outcome<std::optional<int>> intervalOf(const CliOptions &o) {
    bool ok = true;
    const int ms = o.values.value(QStringLiteral("interval"), QStringLiteral("1000")).toInt(&ok);
    if (!ok || ms < 0)
        return base::failure(CliMonitorTr::tr(
            "tipscope-cli: --interval takes milliseconds (0: as fast as the line allows)"));
    return std::optional<int>(ms);
}

// The lines to monitor: the workspace's, or the one the options name; demo lines at work.
base::Outcome<WorkspaceFile> linesOf(const CliOptions &o) {
    WorkspaceFile file;
    if (o.workspace.isEmpty()) {
        file.lines = {workspaceLineOf(o)};
        return file;
    }
    auto loaded = WorkspaceFile::load(o.workspace);
    if (!loaded)
        return base::failure(QStringLiteral("tipscope-cli: ") + loaded.error());
    if (loaded->lines.isEmpty())
        return base::failure(
            CliMonitorTr::tr("tipscope-cli: the workspace %1 has no lines").arg(o.workspace));
    file = loaded.value();
    for (WorkspaceLine &line : file.lines)
        if (line.session.line.kind == link::LineSettings::Kind::Demo)
            line.session.demoActivity = true;
    return file;
}

// Each line's CSV file (its own, or the workspace's one file); none without --csv. One line's
// file or the shared one is created now, so a path that cannot be written is refused before
// anything runs; a workspace line's own file once the line has a station, so a line that never
// comes up leaves no empty file.
base::Outcome<void> openCsv(const CliOptions &o, std::vector<MonitoredLine> &lines) {
    if (!o.values.contains(QStringLiteral("csv")))
        return {};
    const QString path = o.values.value(QStringLiteral("csv"));
    if (o.flags.contains(QStringLiteral("csv-one-file"))) {
        auto shared = MonitorCsv::create(path, true);
        if (!shared)
            return base::failure(shared.error());
        for (MonitoredLine &line : lines)
            line.csv = shared.value();
        return {};
    }
    if (o.workspace.isEmpty()) {
        auto own = MonitorCsv::create(path, false);
        if (!own)
            return base::failure(own.error());
        lines.front().csv = own.value();
        return {};
    }
    const QFileInfo folder(QFileInfo(path).absolutePath());
    if (!folder.isDir() || !folder.isWritable())
        return base::failure(CliMonitorTr::tr("tipscope-cli: cannot write %1: %2")
                                 .arg(folder.filePath(), folder.isDir()
                                                             ? CliMonitorTr::tr("permission denied")
                                                             : CliMonitorTr::tr("no such folder")));
    QHash<QString, QString> lineOfFile;
    for (MonitoredLine &line : lines) {
        line.csvPath = MonitorCsv::fileFor(path, line.name);
        // Names made safe may meet: two lines must not write, and truncate, one file.
        if (const auto other = lineOfFile.constFind(line.csvPath); other != lineOfFile.cend())
            return base::failure(
                CliMonitorTr::tr("tipscope-cli: lines %1 and %2 would both write %3; rename one")
                    .arg(base::elided(*other), base::elided(line.name),
                         base::elidedPath(line.csvPath)));
        lineOfFile.insert(line.csvPath, line.name);
    }
    return {};
}

// A monitor of one line stops when the line cannot be opened or holds no station; a workspace's
// lines are waited for, each as long as the monitor runs.
int firstContact(MonitoredLine &line, QTextStream &err) {
    Session &session = *line.session;
    QEventLoop wait;
    QTimer giveUp;
    giveUp.setSingleShot(true);
    QObject::connect(&giveUp, &QTimer::timeout, &wait, &QEventLoop::quit);
    QObject::connect(&session, &Session::stateChanged, &wait, [&wait](Session::State state) {
        if (state != Session::State::Connecting && state != Session::State::Detecting)
            wait.quit();
    });
    giveUp.start(kFirstContactMs);
    if (session.state() == Session::State::Connecting ||
        session.state() == Session::State::Detecting)
        wait.exec();
    if (session.state() != Session::State::Connected) {
        err << "tipscope-cli: " << session.stateText() << Qt::endl;
        return kTransport;
    }
    if (session.devices().isEmpty()) {
        err << "tipscope-cli: " << session.stateText() << Qt::endl;
        return kNoAnswer;
    }
    if (!session.station()) {
        err << CliMonitorTr::tr("tipscope-cli: monitor needs a station; none was found")
            << Qt::endl;
        return kUsage;
    }
    return kOk;
}

// At the end, per line: a line that never came up, or is down, failed; one without a station
// was never monitored.
int outcomeOf(const MonitoredLine &line) {
    if (line.session->isPlayback())
        return line.everConnected && line.session->state() == Session::State::Disconnected
                   ? kOk
                   : kRefused;
    if (!line.everConnected || line.session->state() != Session::State::Connected)
        return kTransport;
    if (!line.session->station())
        return line.session->devices().isEmpty() ? kNoAnswer : kUsage;
    return line.lastCycleWhole ? kOk : kTransport;
}

} // namespace

int runMonitor(const CliOptions &o, QTextStream &out, QTextStream &err) {
    const auto interval = intervalOf(o);
    if (!interval) {
        err << interval.error() << Qt::endl;
        return kUsage;
    }
    bool ok = true;
    const double durationS =
        o.values.value(QStringLiteral("duration"), QStringLiteral("0")).toDouble(&ok);
    if (!ok || !std::isfinite(durationS) || durationS < 0 || durationS > 1e9) {
        err << CliMonitorTr::tr("tipscope-cli: --duration takes seconds") << Qt::endl;
        return kUsage;
    }
    service::LineService::Options options;
    options.journalPath = journalPathOf(o);
    if (o.values.contains(QStringLiteral("limit"))) {
        const auto rule = JointLimitRules::parseRule(o.values.value(QStringLiteral("limit")));
        if (!rule) {
            err << "tipscope-cli: --limit: " << rule.error() << Qt::endl;
            return kRefused;
        }
        options.extraRules.append(rule.value());
    }
    const auto file = linesOf(o);
    if (!file) {
        err << file.error() << Qt::endl;
        return kUsage;
    }
    std::vector<MonitoredLine> lines(size_t(file->lines.size()));
    for (size_t i = 0; i < lines.size(); ++i) {
        lines[i].name = file->lines.at(qsizetype(i)).name;
        if (!o.workspace.isEmpty())
            lines[i].prefix = QStringLiteral("[%1] ").arg(lines[i].name);
    }
    if (const auto csv = openCsv(o, lines); !csv) {
        err << csv.error() << Qt::endl;
        return kUsage;
    }

    service::LineService service;
    if (const auto started = service.start(options); !started) {
        err << "tipscope-cli: " << started.error() << Qt::endl;
        return kRefused;
    }
    journal::Journal &journal = service.journal();
    QObject::connect(&journal, &journal::Journal::stateChanged, &journal,
                     [&journal, &err](journal::JournalState state) {
                         if (state == journal::JournalState::Failed)
                             err << "# " << journal.errorText() << Qt::endl;
                     });
    if (journal::WorkContextFollower *context = service.workContext())
        QObject::connect(context, &journal::WorkContextFollower::unreadable, &journal,
                         [&err](const QString &why) { err << "# " << why << Qt::endl; });
    service.openLines(file.value());
    for (size_t i = 0; i < lines.size(); ++i) {
        lines[i].session = service.workspace().session(int(i));
        followLine(lines[i], err);
    }
    QObject::connect(&service, &service::LineService::jointEnded, &service,
                     [&lines, &out](int line, const JointRecord &joint) {
                         if (line >= 0 && line < int(lines.size()))
                             out << lines[size_t(line)].prefix << jointLine(joint) << Qt::endl;
                     });
    if (o.workspace.isEmpty())
        if (const int rc = firstContact(lines.front(), err); rc != kOk)
            return rc;

    QEventLoop loop;
    QTimer cycle;
    QObject::connect(&cycle, &QTimer::timeout, &loop, [&lines, &out, &err] {
        for (MonitoredLine &line : lines)
            printCycle(line, out, err);
    });
    // 0: as fast as the line allows, so at every new sample of the line.
    if (*interval.value() > 0) {
        cycle.start(*interval.value());
    } else {
        for (MonitoredLine &line : lines)
            QObject::connect(&line.session->telemetry(), &Telemetry::samplesAdded, &loop,
                             [&line, &out, &err] { printCycle(line, out, err); });
    }
    if (durationS > 0)
        QTimer::singleShot(qint64(durationS * 1000), &loop, &QEventLoop::quit);
    // Lines that are all recordings are over once each is played (or refused).
    const auto played = [&lines] {
        return std::all_of(lines.begin(), lines.end(), [](const MonitoredLine &line) {
            const Session::State state = line.session->state();
            return line.session->isPlayback() &&
                   (state == Session::State::Disconnected || state == Session::State::Failed);
        });
    };
    for (MonitoredLine &line : lines)
        QObject::connect(line.session, &Session::stateChanged, &loop, [&loop, played] {
            if (played())
                loop.quit();
        });
    catchStopSignals();
    quitLoopOnStop(loop);
    if (!played())
        loop.exec();

    int worst = kOk;
    for (const MonitoredLine &line : lines)
        worst = qMax(worst, outcomeOf(line));
    // A CSV that could not be written whole: the run did not do what was asked.
    if (std::any_of(lines.begin(), lines.end(), [](const MonitoredLine &l) { return l.csvFailed; }))
        worst = qMax(worst, int(kUsage));
    if (!service.finish(kFinishMs)) {
        err << "# "
            << CliMonitorTr::tr("%1 records could not be kept in the journal %2: %3")
                   .arg(journal.pendingCount() + journal.lostCount())
                   .arg(journal.path(), journal.errorText())
            << Qt::endl;
        worst = qMax(worst, int(kTransport));
    }
    return worst;
}

} // namespace tipscope::cli
