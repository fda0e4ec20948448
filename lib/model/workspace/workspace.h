// Workspace: the lines of a WorkspaceFile, open at once, one Session each.
//
// open() closes what was open and connects every line of the file; each Session keeps its own
// request queue, poll scheduler, reconnection and statistics, so a line that is down, slow or
// absent never holds up the others. Each line's joints are judged by the line's own limits, or
// the shared ones (setSharedLimits()) when the line names none. The workspace owns the sessions;
// a session() pointer stays valid until close() or the next open(). lineStateChanged() and
// lineDevicesChanged() repeat a session's signals with the line's index; linesChanged() says the
// set of lines changed (open, addLine, close).
//
// A workspace watches a fleet: every port of every station is polled at the live interval, shown
// or not, so each line's joints are found and its tiles are current. Each line's scheduler also
// fills its wire (PollScheduler::setFillWire()): a line polls as fast as its own wire carries,
// which costs no other line.
#pragma once

#include "model/workspace/workspacefile.h"

#include <QObject>
#include <memory>
#include <vector>

namespace tipscope::model {

class Workspace : public QObject {
    Q_OBJECT
public:
    explicit Workspace(QObject *parent = nullptr);
    ~Workspace() override;

    void open(const WorkspaceFile &file);
    // Adds a line to those open and connects it; the others carry on. Refuses a name in use.
    base::Outcome<void> addLine(const WorkspaceLine &line);
    void close();

    [[nodiscard]] const WorkspaceFile &file() const { return m_file; }
    [[nodiscard]] int count() const { return int(m_sessions.size()); }
    [[nodiscard]] const WorkspaceLine &line(int index) const { return m_file.lines.at(index); }
    [[nodiscard]] Session *session(int index) const { return m_sessions.at(size_t(index)).get(); }
    // The index of the line named `name`, or -1.
    [[nodiscard]] int indexOf(const QString &name) const;
    // The index of the line that reaches `device` (a device found on it, or the recording it
    // plays), or -1 for a device none of the lines has found.
    [[nodiscard]] int lineOf(const DeviceIdentity &device) const;
    // What people call `device`: the name its line gives its address, else its model.
    [[nodiscard]] QString deviceName(int index, const DeviceModel &device) const;

    // The limits of lines that name none (by default, the built-in defaults).
    void setSharedLimits(const JointLimitRules &rules);
    [[nodiscard]] JointLimitRules limitsOf(int index) const;

Q_SIGNALS:
    void linesChanged();
    void lineStateChanged(int index, tipscope::model::Session::State state, const QString &text);
    void lineDevicesChanged(int index);

private:
    void startSession(int index);
    // Connects the line's session as the file says, and plays it when it is a recording.
    void connectLine(int index);

    WorkspaceFile m_file;
    JointLimitRules m_shared;
    std::vector<std::unique_ptr<Session>> m_sessions;
};

} // namespace tipscope::model
