#include "model/workspace/workspacefile.h"

#include "base/atomicsave.h"
#include "base/elide.h"
#include "base/jsonfile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

namespace tipscope::model {

namespace {
struct WorkspaceFileTr {
    Q_DECLARE_TR_FUNCTIONS(WorkspaceFile)
};

using base::failure;
using base::Outcome;

const QString kFormat = QStringLiteral("tipscope-workspace");
constexpr qint64 kMaxBytes = 4 * 1024 * 1024;

// The header: this is a workspace, of a version this TipScope reads.
Outcome<void> checkHeader(const QJsonObject &json) {
    if (json.value(QStringLiteral("format")).toString() != kFormat)
        return failure(WorkspaceFileTr::tr("not a TipScope workspace (\"format\" is not \"%1\")")
                           .arg(kFormat));
    const QJsonValue version = json.value(QStringLiteral("version"));
    if (!version.isDouble() || version.toDouble() < 1 ||
        version.toDouble() != double(version.toInt()))
        return failure(WorkspaceFileTr::tr("\"version\" must be a whole number from 1"));
    if (version.toInt() > WorkspaceFile::kVersion)
        return failure(WorkspaceFileTr::tr(
                           "written by a later TipScope (workspace version %1); this one reads "
                           "version %2 and older")
                           .arg(version.toInt())
                           .arg(WorkspaceFile::kVersion));
    return {};
}
} // namespace

const WorkspaceLine *WorkspaceFile::line(const QString &name) const {
    for (const WorkspaceLine &l : lines)
        if (l.name == name)
            return &l;
    return nullptr;
}

QJsonObject WorkspaceFile::toJson() const {
    QJsonArray list;
    for (const WorkspaceLine &l : lines)
        list.append(workspaceLineToJson(l));
    return {{QStringLiteral("format"), kFormat},
            {QStringLiteral("version"), kVersion},
            {QStringLiteral("lines"), list}};
}

Outcome<WorkspaceFile> WorkspaceFile::fromJson(const QJsonObject &json) {
    if (const auto header = checkHeader(json); !header)
        return failure(header.error());
    if (!json.value(QStringLiteral("lines")).isArray())
        return failure(WorkspaceFileTr::tr("\"lines\" must be a list of lines"));
    const QJsonArray list = json.value(QStringLiteral("lines")).toArray();
    WorkspaceFile file;
    QSet<QString> names;
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString name = list.at(i).toObject().value(QStringLiteral("name")).toString();
        const QString which =
            name.isEmpty() ? WorkspaceFileTr::tr("line %1").arg(i + 1)
                           : WorkspaceFileTr::tr("line %1 (%2)").arg(i + 1).arg(base::elided(name));
        if (!list.at(i).isObject())
            return failure(WorkspaceFileTr::tr("%1: must be an object").arg(which));
        const auto line = workspaceLineFromJson(list.at(i).toObject());
        if (!line)
            return failure(QStringLiteral("%1: %2").arg(which, line.error()));
        if (names.contains(line->name))
            return failure(WorkspaceFileTr::tr(
                               "%1: the name is already another line's; each line needs its own")
                               .arg(which));
        names.insert(line->name);
        file.lines.append(line.value());
    }
    return file;
}

Outcome<WorkspaceFile> WorkspaceFile::load(const QString &path) {
    const auto read = base::io::readJsonObject(path, kMaxBytes);
    // The path may come from another file (an agent's configuration): quoted cut, as any echo.
    const QString shown = base::elidedPath(path);
    if (const auto *problem = std::get_if<base::io::JsonFileProblem>(&read)) {
        using Kind = base::io::JsonFileProblem::Kind;
        switch (problem->kind) {
        case Kind::Missing:
            return failure(WorkspaceFileTr::tr("cannot read the workspace %1: %2")
                               .arg(shown, WorkspaceFileTr::tr("there is no such file")));
        case Kind::Unreadable:
            return failure(WorkspaceFileTr::tr("cannot read the workspace %1: %2")
                               .arg(shown, problem->detail));
        case Kind::TooBig:
            return failure(WorkspaceFileTr::tr("the workspace %1 is too big to be one").arg(shown));
        case Kind::NotAnObject:
            return failure(WorkspaceFileTr::tr("the workspace %1 is not a JSON object: %2")
                               .arg(shown, problem->detail.isEmpty()
                                               ? WorkspaceFileTr::tr("it is a list")
                                               : problem->detail));
        }
    }
    const auto parsed = fromJson(std::get<QJsonObject>(read));
    if (!parsed)
        return failure(QStringLiteral("%1: %2").arg(shown, parsed.error()));
    WorkspaceFile file = parsed.value();
    // A recording named relative to the workspace is found beside it, from any working folder.
    const QDir folder = QFileInfo(path).absoluteDir();
    for (WorkspaceLine &line : file.lines)
        if (!line.session.recordingPath.isEmpty())
            line.session.recordingPath = folder.absoluteFilePath(line.session.recordingPath);
    return file;
}

Outcome<void> WorkspaceFile::save(const QString &path) const {
    QDir().mkpath(QFileInfo(path).absolutePath());
    return base::io::saveAtomically(path, QJsonDocument(toJson()).toJson(QJsonDocument::Indented));
}

} // namespace tipscope::model
