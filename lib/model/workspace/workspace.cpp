#include "model/workspace/workspace.h"

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
    for (int i = 0; i < int(m_file.lines.size()); ++i) {
        auto session = std::make_unique<Session>();
        session->scheduler().setFillWire(true);
        session->joints().setRules(limitsOf(i));
        connect(session.get(), &Session::stateChanged, this,
                [this, i](Session::State state, const QString &text) {
                    Q_EMIT lineStateChanged(i, state, text);
                });
        connect(session.get(), &Session::devicesChanged, this,
                [this, i] { Q_EMIT lineDevicesChanged(i); });
        m_sessions.push_back(std::move(session));
    }
    Q_EMIT linesChanged();
    // Connected after every session exists, so a line's signals find all the others in place.
    for (int i = 0; i < count(); ++i)
        m_sessions.at(size_t(i))->connectTo(m_file.lines.at(i).session);
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
