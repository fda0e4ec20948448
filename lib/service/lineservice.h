// LineService: the one path from the wire to the journal, opened by every front end.
//
// start() opens the journal, reads the shared joint limits and follows the work context file
// beside the journal; openLines() opens a workspace's lines (one line or many), each a Session
// with its own request queue, poll scheduler, reconnection and joint watcher. Every line's joints
// and events are kept in the journal (SessionJournal), stamped with the line's own work context
// or the journal's, and every line's joints are judged by its own limits or the shared ones. A
// session the service does not own (the window's connection-bar line) is kept the same way with
// keep(). A front end then only prints, draws or publishes what the sessions and the journal
// hold: it polls nothing and measures nothing itself, so the window, the command line and the
// agent find the same joints in the same samples.
//
// The service owns the journal and the workspace; a kept session must outlive its keeping or be
// released first.
#pragma once

#include "journal/journal.h"
#include "journal/sessionjournal.h"
#include "journal/workcontextfile.h"
#include "model/joints/jointlimitrules.h"
#include "model/workspace/workspace.h"

#include <QObject>
#include <map>
#include <memory>
#include <vector>

namespace tipscope::service {

class LineService : public QObject {
    Q_OBJECT
public:
    struct Options {
        QString journalPath; // empty: the journal every TipScope program shares
        // The joint limits file; empty: the shared one (model::defaultJointLimitsPath()).
        QString limitsPath;
        // Rules on top of the file's (`tipscope-cli monitor --limit`).
        QList<model::JointLimitRule> extraRules;
        // Follow the work context file beside the journal: each change stamps what follows.
        bool followWorkContext = true;
    };

    explicit LineService(QObject *parent = nullptr);
    ~LineService() override;

    // Opens the journal and reads the limits. A limits file that cannot be read is refused,
    // before anything is judged by limits nobody set; the journal opens either way (a journal
    // that cannot be written says so in its own state, and holds its records until it can).
    [[nodiscard]] base::Outcome<void> start(const Options &options);
    // Closes the lines open and opens those of `file`.
    void openLines(const model::WorkspaceFile &file);
    void closeLines();
    void keep(model::Session &session);
    void release(model::Session &session);
    // Reads the limits file again (the window saved new limits), for every line and kept session.
    [[nodiscard]] base::Outcome<void> reloadLimits();
    // Ends every joint in progress (as incomplete: it was not seen to its end) and waits up to
    // `ms` for the journal; false when a record could not be kept (the journal says why).
    [[nodiscard]] bool finish(int ms);

    [[nodiscard]] model::Workspace &workspace() { return m_workspace; }
    [[nodiscard]] journal::Journal &journal() { return *m_journal; }
    [[nodiscard]] bool isStarted() const { return m_journal != nullptr; }
    // Null when the work context file is not followed.
    [[nodiscard]] journal::WorkContextFollower *workContext() const { return m_context.get(); }
    [[nodiscard]] const model::JointLimitRules &sharedLimits() const { return m_limits; }

Q_SIGNALS:
    // A session's joint was ended and handed to the journal: `line` is its workspace index, or
    // -1 for a kept session.
    void jointEnded(int line, const tipscope::model::JointRecord &joint);
    void limitsChanged();

private:
    void keepLines();
    void applyLimits();

    Options m_options;
    std::unique_ptr<journal::Journal> m_journal;
    std::unique_ptr<journal::WorkContextFollower> m_context;
    model::JointLimitRules m_limits;
    model::Workspace m_workspace;
    std::vector<std::unique_ptr<journal::SessionJournal>> m_keptLines;
    std::map<model::Session *, std::unique_ptr<journal::SessionJournal>> m_keptSessions;
};

} // namespace tipscope::service
