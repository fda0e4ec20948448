#include "cliworkspace.h"

#include "clicommands.h"
#include "climonitorcsv.h"
#include "cliprefixedoutput.h"

#include "model/workspace/workspacefile.h"

#include <QThread>
#include <memory>
#include <vector>

namespace tipscope::cli {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(CliWorkspace)
};

// The command line's options for one line of the workspace.
CliOptions optionsFor(const CliOptions &o, const model::WorkspaceLine &line) {
    CliOptions l = o;
    l.lineName = line.name;
    l.line = line.session.line;
    l.demo = l.demoActivity = line.session.line.kind == link::LineSettings::Kind::Demo;
    l.addressing = CliOptions::Addressing(int(line.session.addressing));
    l.targetAddress = line.session.targetAddress;
    if (line.session.scanAllAddresses && !l.flags.contains(QStringLiteral("scan")))
        l.flags.append(QStringLiteral("scan"));
    l.lineLimits = line.jointLimits;
    if (!line.context.isEmpty())
        l.lineContext = line.context;
    if (o.values.contains(QStringLiteral("csv")) && !o.sharedCsv)
        l.values.insert(QStringLiteral("csv"),
                        MonitorCsv::fileFor(o.values.value(QStringLiteral("csv")), line.name));
    // A monitor waits for a line that is down at the start, as it does for one lost later.
    l.line.retryInitialOpen = o.command == QLatin1String("monitor");
    return l;
}

QString prefixOf(const QString &name) {
    return QStringLiteral("[%1] ").arg(name);
}

// One line's command, on a thread of its own: its line, queue and waits never touch another's.
class LineRun : public QThread {
public:
    explicit LineRun(CliOptions options)
        : m_options(std::move(options)) {}
    [[nodiscard]] int exitCode() const { return m_exitCode; }

protected:
    void run() override {
        PrefixedOutput out(prefixOf(m_options.lineName), stdout);
        PrefixedOutput err(prefixOf(m_options.lineName), stderr);
        CliSession s(m_options, &out, &err);
        m_exitCode = s.open(waitLimitMs());
        if (m_exitCode == kOk)
            m_exitCode = runOnLine(s);
    }

private:
    // A monitor with a duration waits for its line no longer than it would monitor.
    [[nodiscard]] int waitLimitMs() const {
        const double s = m_options.values.value(QStringLiteral("duration")).toDouble();
        return s > 0 && s < 1e6 ? int(s * 1000) : 0;
    }

    CliOptions m_options;
    int m_exitCode = kTransport;
};

int runJointsPerLine(const QList<CliOptions> &lines) {
    int worst = kOk;
    for (const CliOptions &l : lines) {
        PrefixedOutput outDevice(prefixOf(l.lineName), stdout);
        PrefixedOutput errDevice(prefixOf(l.lineName), stderr);
        QTextStream out(&outDevice), err(&errDevice);
        worst = qMax(worst, runJoints(l, out, err));
    }
    return worst;
}

} // namespace

int runWorkspace(const CliOptions &options, QTextStream &out, QTextStream &err) {
    const auto file = model::WorkspaceFile::load(options.workspace);
    if (!file) {
        err << "tipscope-cli: " << file.error() << Qt::endl;
        return kUsage;
    }
    if (file->lines.isEmpty()) {
        err << Tr::tr("tipscope-cli: the workspace %1 has no lines").arg(options.workspace)
            << Qt::endl;
        return kUsage;
    }
    CliOptions common = options;
    if (options.flags.contains(QStringLiteral("csv-one-file"))) {
        auto csv = MonitorCsv::create(options.values.value(QStringLiteral("csv")), true);
        if (!csv) {
            err << csv.error() << Qt::endl;
            return kUsage;
        }
        common.sharedCsv = csv.value();
    }
    QList<CliOptions> lines;
    for (const model::WorkspaceLine &line : file->lines)
        lines.append(optionsFor(common, line));
    out.flush();
    if (options.command == QLatin1String("joints"))
        return runJointsPerLine(lines);
    std::vector<std::unique_ptr<LineRun>> runs;
    for (const CliOptions &l : lines) {
        runs.push_back(std::make_unique<LineRun>(l));
        runs.back()->start();
    }
    int worst = kOk;
    for (const auto &run : runs) {
        run->wait();
        worst = qMax(worst, run->exitCode());
    }
    return worst;
}

} // namespace tipscope::cli
