#include "workcontextfile.h"

#include "base/atomicsave.h"
#include "base/jsonfile.h"
#include "model/context/workcontextjson.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>

namespace tipscope::journal {

namespace {
struct WorkContextFileTr {
    Q_DECLARE_TR_FUNCTIONS(WorkContextFile)
};

using base::failure;
using base::Outcome;

constexpr qint64 kMaxBytes = 64 * 1024;
} // namespace

QString workContextPathFor(const QString &journalPath) {
    const QString journal = journalPath.isEmpty() ? Journal::defaultPath() : journalPath;
    return QFileInfo(journal).dir().filePath(QStringLiteral("context.json"));
}

Outcome<model::WorkContext> readWorkContext(const QString &path) {
    const auto read = base::io::readJsonObject(path, kMaxBytes);
    if (const auto *problem = std::get_if<base::io::JsonFileProblem>(&read)) {
        using Kind = base::io::JsonFileProblem::Kind;
        switch (problem->kind) {
        case Kind::Missing:
            return model::WorkContext{};
        case Kind::Unreadable:
            return failure(WorkContextFileTr::tr("cannot read the work context %1: %2")
                               .arg(path, problem->detail));
        case Kind::TooBig:
            return failure(
                WorkContextFileTr::tr("the work context %1 is too big to be one").arg(path));
        case Kind::NotAnObject:
            return failure(WorkContextFileTr::tr("the work context %1 is not a JSON object: %2")
                               .arg(path, problem->detail));
        }
    }
    const auto context = model::workContextFromJson(std::get<QJsonObject>(read));
    if (!context)
        return failure(WorkContextFileTr::tr("the work context %1: %2").arg(path, context.error()));
    return context;
}

Outcome<void> writeWorkContext(const QString &path, const model::WorkContext &context) {
    // What every reader would refuse is never written.
    if (const QString why = model::workContextProblem(context); !why.isEmpty())
        return failure(why);
    QDir().mkpath(QFileInfo(path).absolutePath());
    return base::io::saveAtomically(
        path, QJsonDocument(model::workContextToJson(context)).toJson(QJsonDocument::Indented));
}

WorkContextFollower::WorkContextFollower(Journal &journal, const QString &path, QObject *parent)
    : QObject(parent)
    , m_journal(journal)
    , m_path(QFileInfo(path).absoluteFilePath()) {
    QDir().mkpath(QFileInfo(m_path).absolutePath());
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &WorkContextFollower::reread);
    connect(&m_watcher, &QFileSystemWatcher::directoryChanged, this, &WorkContextFollower::reread);
    watch();
    reread();
}

Outcome<void> WorkContextFollower::set(const model::WorkContext &context) {
    const auto saved = writeWorkContext(m_path, context);
    if (saved)
        reread();
    return saved;
}

void WorkContextFollower::watch() {
    const QString dir = QFileInfo(m_path).absolutePath();
    if (!m_watcher.directories().contains(dir))
        m_watcher.addPath(dir);
    if (QFile::exists(m_path) && !m_watcher.files().contains(m_path))
        m_watcher.addPath(m_path);
}

void WorkContextFollower::reread() {
    watch(); // an atomic save replaced the file the watcher followed
    const auto context = readWorkContext(m_path);
    if (!context) {
        Q_EMIT unreadable(context.error());
        return;
    }
    if (context.value() == m_journal.context())
        return;
    m_journal.setContext(context.value());
    Q_EMIT contextChanged(context.value());
}

} // namespace tipscope::journal
