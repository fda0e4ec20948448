#include "model/workspace/workspace.h"

#include "model/recording/recordingplayback.h"

namespace tipscope::model {

Workspace::Workspace(QObject *parent)
    : QObject(parent) {}

Workspace::~Workspace() {
    // The sessions go first: their devices still report to them while they close.
    m_sessions.clear();
}

void Workspace::open(const WorkspaceFile &file) {
    close();
    m_file = file;
    for (int i = 0; i < int(m_file.lines.size()); ++i)
        startSession(i);
    Q_EMIT linesChanged();
    // Connected after every session exists, so a line's signals find all the others in place.
    for (int i = 0; i < count(); ++i)
        connectLine(i);
}

base::Outcome<void> Workspace::addLine(const WorkspaceLine &line) {
    if (line.name.trimmed().isEmpty())
        return base::failure(tr("a line needs a name"));
    if (indexOf(line.name) >= 0)
        return base::failure(tr("the workspace already has a line named \"%1\"").arg(line.name));
    m_file.lines.append(line);
    const int index = count();
    startSession(index);
    Q_EMIT linesChanged();
    connectLine(index);
    return {};
}

void Workspace::connectLine(int i) {
    Session &session = *m_sessions.at(size_t(i));
    session.connectTo(m_file.lines.at(i).session);
    if (session.isPlayback())
        RecordingPlayback::start(session);
}

void Workspace::startSession(int i) {
    auto session = std::make_unique<Session>();
    session->scheduler().setFillWire(true);
    session->joints().setRules(limitsOf(i));
    Session *s = session.get();
    connect(s, &Session::stateChanged, this, [this, i](Session::State state, const QString &text) {
        Q_EMIT lineStateChanged(i, state, text);
    });
    connect(s, &Session::devicesChanged, this, [this, i, s] {
        for (DeviceModel *d : s->devices()) {
            if (auto *station = qobject_cast<StationModel *>(d)) {
                QSet<int> every;
                for (const PortModel *port : station->ports())
                    every.insert(port->number());
                s->scheduler().setVisiblePorts(station, every);
            }
        }
        Q_EMIT lineDevicesChanged(i);
    });
    m_sessions.push_back(std::move(session));
}

void Workspace::close() {
    if (m_sessions.empty() && m_file.lines.isEmpty())
        return;
    m_sessions.clear();
    m_file = {};
    Q_EMIT linesChanged();
}

int Workspace::indexOf(const QString &name) const {
    for (int i = 0; i < count(); ++i)
        if (m_file.lines.at(i).name == name)
            return i;
    return -1;
}

int Workspace::lineOf(const DeviceIdentity &device) const {
    for (int i = 0; i < count(); ++i) {
        const Session &s = *m_sessions.at(size_t(i));
        if (s.isPlayback() && s.playbackLine() == device.line)
            return i;
        for (const DeviceModel *found : s.devices())
            if (found->identity().line == device.line)
                return i;
    }
    return -1;
}

QString Workspace::deviceName(int index, const DeviceModel &device) const {
    const QString given = line(index).deviceName(device.address());
    return given.isEmpty() ? device.info().model : given;
}

void Workspace::setSharedLimits(const JointLimitRules &rules) {
    m_shared = rules;
    for (int i = 0; i < count(); ++i)
        m_sessions.at(size_t(i))->joints().setRules(limitsOf(i));
}

JointLimitRules Workspace::limitsOf(int index) const {
    return line(index).jointLimits.value_or(m_shared);
}

} // namespace tipscope::model
