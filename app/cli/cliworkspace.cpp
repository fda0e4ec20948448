#include "cliworkspace.h"

#include "clicommands.h"
#include "cliprefixedoutput.h"

#include "model/workspace/workspacefile.h"

#include <QBuffer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QThread>
#include <memory>
#include <vector>

namespace tipscope::cli {

namespace {

struct CliWorkspaceTr {
    Q_DECLARE_TR_FUNCTIONS(CliWorkspace)
};

// The command line's options for one line of the workspace.
CliOptions optionsFor(const CliOptions &o, const model::WorkspaceLine &line) {
    CliOptions l = o;
    l.lineName = line.name;
    l.line = line.session.line;
    l.demo = l.demoActivity = line.session.line.kind == link::LineSettings::Kind::Demo;
    l.addressing = line.session.addressing;
    l.targetAddress = line.session.targetAddress;
    if (line.session.scanAllAddresses && !l.flags.contains(QStringLiteral("scan")))
        l.flags.append(QStringLiteral("scan"));
    return l;
}

QString prefixOf(const QString &name) {
    return QStringLiteral("[%1] ").arg(name);
}

// What one line's run leaves for the workspace's JSON document: its exit code, its standard output
// (one JSON document of its own) and what it said on standard error.
struct LineResult {
    QString name;
    int exitCode = kTransport;
    QByteArray json;
    QString said;
};

// One line's command, on a thread of its own: its line, queue and waits never touch another's.
// With --json its standard output is kept for the one document of the workspace, not prefixed.
class LineRun : public QThread {
public:
    LineRun(CliOptions options, bool keepJson)
        : m_options(std::move(options))
        , m_keepJson(keepJson) {
        m_result.name = m_options.lineName;
    }
    [[nodiscard]] const LineResult &result() const { return m_result; }

protected:
    void run() override {
        QBuffer json(&m_result.json);
        json.open(QIODevice::WriteOnly);
        PrefixedOutput out(prefixOf(m_options.lineName), stdout);
        PrefixedOutput err(prefixOf(m_options.lineName), stderr, PrefixedOutput::Keep::Text);
        {
            CliSession s(m_options, m_keepJson ? static_cast<QIODevice *>(&json) : &out, &err);
            m_result.exitCode = s.open();
            if (m_result.exitCode == kOk)
                m_result.exitCode = runOnLine(s);
        } // the session's streams flush as it goes
        err.close();
        m_result.said = err.keptText();
    }

private:
    CliOptions m_options;
    bool m_keepJson;
    LineResult m_result;
};

// {"line": NAME, "exitCode": N, KEY: the line's own document, "messages": [...]}: a line that
// failed has no KEY and says why in its messages.
QJsonObject lineJson(const LineResult &r, const QString &key) {
    QJsonObject o{{QStringLiteral("line"), r.name}, {QStringLiteral("exitCode"), r.exitCode}};
    QJsonParseError parsed{};
    const QJsonDocument doc = QJsonDocument::fromJson(r.json, &parsed);
    if (parsed.error == QJsonParseError::NoError)
        o.insert(key, doc.isArray() ? QJsonValue(doc.array()) : QJsonValue(doc.object()));
    QJsonArray messages;
    for (const QString &m : r.said.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        messages.append(m);
    if (!messages.isEmpty())
        o.insert(QStringLiteral("messages"), messages);
    return o;
}

// The workspace's lines in one JSON document, in the file's order, for a program to read whole.
void printDocument(const CliOptions &o, const QList<LineResult> &results, QTextStream &out) {
    const QString key =
        o.command == QLatin1String("joints") ? QStringLiteral("joints") : QStringLiteral("devices");
    QJsonArray lines;
    for (const LineResult &r : results)
        lines.append(lineJson(r, key));
    out << QJsonDocument(
               QJsonObject{{QStringLiteral("workspace"), QFileInfo(o.workspace).absoluteFilePath()},
                           {QStringLiteral("command"), o.command},
                           {QStringLiteral("lines"), lines}})
               .toJson(QJsonDocument::Indented);
    out.flush();
}

int worstOf(const QList<LineResult> &results) {
    int worst = kOk;
    for (const LineResult &r : results)
        worst = qMax(worst, r.exitCode);
    return worst;
}

QList<LineResult> runJointsPerLine(const QList<CliOptions> &lines, bool keepJson) {
    QList<LineResult> results;
    for (const CliOptions &l : lines) {
        LineResult r;
        r.name = l.lineName;
        QBuffer json(&r.json);
        json.open(QIODevice::WriteOnly);
        PrefixedOutput outDevice(prefixOf(l.lineName), stdout);
        PrefixedOutput errDevice(prefixOf(l.lineName), stderr, PrefixedOutput::Keep::Text);
        {
            QTextStream out(keepJson ? static_cast<QIODevice *>(&json) : &outDevice);
            QTextStream err(&errDevice);
            r.exitCode = runJoints(l, out, err);
        }
        errDevice.close();
        r.said = errDevice.keptText();
        results.append(r);
    }
    return results;
}

} // namespace

int runWorkspace(const CliOptions &options, QTextStream &out, QTextStream &err) {
    const auto file = model::WorkspaceFile::load(options.workspace);
    if (!file) {
        err << "tipscope-cli: " << file.error() << Qt::endl;
        return kUsage;
    }
    if (file->lines.isEmpty()) {
        err << CliWorkspaceTr::tr("tipscope-cli: the workspace %1 has no lines")
                   .arg(options.workspace)
            << Qt::endl;
        return kUsage;
    }
    QList<CliOptions> lines;
    for (const model::WorkspaceLine &line : file->lines)
        lines.append(optionsFor(options, line));
    out.flush();
    const bool oneDocument = options.flags.contains(QStringLiteral("json"));
    QList<LineResult> results;
    if (options.command == QLatin1String("joints")) {
        results = runJointsPerLine(lines, oneDocument);
    } else {
        std::vector<std::unique_ptr<LineRun>> runs;
        for (const CliOptions &l : lines) {
            runs.push_back(std::make_unique<LineRun>(l, oneDocument));
            runs.back()->start();
        }
        for (const auto &run : runs) {
            run->wait();
            results.append(run->result());
        }
    }
    if (oneDocument)
        printDocument(options, results, out);
    return worstOf(results);
}

} // namespace tipscope::cli
