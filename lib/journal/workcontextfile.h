// The work context in force (work order, board serial, operator), kept in a small JSON file beside
// the journal, so that every program shares it: `tipscope-cli context set`, a script that writes
// the file, the GUI's context box, and any running monitor or GUI, which follow the file.
//
//     {"work_order": "WO-1234", "board_serial": "SN-0042", "operator": "ana"}
//
// A missing file is an empty context. writeWorkContext() replaces the file atomically, so a
// follower never reads half of it. WorkContextFollower watches the file (and its folder, as an
// atomic save replaces the file) and gives each change to the journal, which stamps it on every
// later joint and event and records the change; a file that cannot be read is reported, and the
// context in force stays as it was.
#pragma once

#include "journal.h"

#include "base/outcome.h"

#include <QFileSystemWatcher>
#include <QObject>

namespace tipscope::journal {

// context.json beside the journal at `journalPath` (by default, Journal::defaultPath()'s).
[[nodiscard]] QString workContextPathFor(const QString &journalPath = QString());
[[nodiscard]] base::Outcome<model::WorkContext> readWorkContext(const QString &path);
[[nodiscard]] base::Outcome<void> writeWorkContext(const QString &path,
                                                   const model::WorkContext &context);

class WorkContextFollower : public QObject {
    Q_OBJECT
public:
    // Reads the file now and whenever it changes; `journal` must outlive this object.
    WorkContextFollower(Journal &journal, const QString &path, QObject *parent = nullptr);

    [[nodiscard]] QString path() const { return m_path; }
    // Writes the file (and so tells every follower, this one included).
    [[nodiscard]] base::Outcome<void> set(const model::WorkContext &context);

Q_SIGNALS:
    void contextChanged(const model::WorkContext &context);
    void unreadable(const QString &reason);

private:
    void reread();
    void watch();

    Journal &m_journal;
    QString m_path;
    QFileSystemWatcher m_watcher;
};

} // namespace tipscope::journal
