#include "model/workspace/linetile.h"

#include "model/events/eventtext.h"
#include "model/workspace/workspace.h"

#include <QDateTime>

namespace tipscope::model {

namespace {

bool isDown(Session::State state) {
    return state == Session::State::Retrying || state == Session::State::Failed ||
           state == Session::State::Disconnected;
}

} // namespace

LineTile::LineTile(const Workspace &workspace, int line, Clock clock, QObject *parent)
    : FleetTileSource(parent)
    , m_workspace(workspace)
    , m_line(line)
    , m_clock(clock ? std::move(clock)
                    : Clock([] { return QDateTime::currentMSecsSinceEpoch(); })) {
    // Down already when the tile is made: since when is not known, and not guessed.
    connect(&workspace, &Workspace::lineStateChanged, this,
            [this](int index, Session::State state) { onStateChanged(index, state); });
}

void LineTile::onStateChanged(int line, Session::State state) {
    if (line != m_line)
        return;
    if (!isDown(state))
        m_downSinceMs.reset();
    else if (!m_downSinceMs)
        m_downSinceMs = m_clock();
    Q_EMIT changed();
}

FleetTileState LineTile::state() const {
    FleetTileState s;
    const WorkspaceLine &line = m_workspace.line(m_line);
    const Session &session = *m_workspace.session(m_line);
    s.deviceName = tr("No device");
    s.lineName = line.name;
    s.cell = line.cell;
    // Up means a device could be reached; until one answers, nothing on this line is known.
    s.lineUp = false;
    s.lineOnly = true;
    if (session.isPlayback()) {
        // A recording has no device to reach: it is "up" while it plays and once played, and
        // needs attention only when it cannot be played; the row under it says how it went.
        const bool refused = session.state() == Session::State::Failed;
        s.deviceName = tr("Recording");
        s.lineUp = !refused;
        s.lineText = refused ? tr("Cannot be played") : QString();
        s.problems.append({refused ? Level::Error : Level::Info, asSentence(session.stateText())});
    } else if (isDown(session.state())) {
        s.downSinceMs = m_downSinceMs;
        s.lineText = FleetTile::downText(m_downSinceMs, m_clock());
        const QString why = session.line() ? session.line()->lastError() : QString();
        s.problems.append({Level::Error, asSentence(why.isEmpty() ? session.stateText() : why)});
    } else {
        const Session::State state = session.state();
        // Connecting is not looking yet: a server that never accepts must not read as a search.
        s.lineText = state == Session::State::Connected    ? tr("No device answered")
                     : state == Session::State::Connecting ? tr("Connecting")
                                                           : tr("Looking for devices");
        s.problems.append({state == Session::State::Connected ? Level::Warning : Level::Info,
                           asSentence(session.stateText())});
    }
    return s;
}

} // namespace tipscope::model
