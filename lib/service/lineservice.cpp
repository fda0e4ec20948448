#include "lineservice.h"

#include "model/joints/jointlimitsfile.h"

namespace tipscope::service {

LineService::LineService(QObject *parent)
    : QObject(parent) {
    connect(&m_workspace, &model::Workspace::linesChanged, this, &LineService::keepLines);
}

LineService::~LineService() {
    // What keeps the sessions goes first, then the sessions, then the journal they wrote to.
    m_keptSessions.clear();
    m_keptLines.clear();
    m_workspace.close();
}

base::Outcome<void> LineService::start(const Options &options) {
    m_options = options;
    m_journal = std::make_unique<journal::Journal>(options.journalPath);
    if (options.followWorkContext)
        m_context = std::make_unique<journal::WorkContextFollower>(
            *m_journal, journal::workContextPathFor(m_journal->path()));
    return reloadLimits();
}

base::Outcome<void> LineService::reloadLimits() {
    const QString path =
        m_options.limitsPath.isEmpty() ? model::defaultJointLimitsPath() : m_options.limitsPath;
    auto rules = model::loadJointLimits(path);
    if (!rules)
        return base::failure(rules.error());
    m_limits = rules.value();
    for (const model::JointLimitRule &rule : std::as_const(m_options.extraRules))
        m_limits.add(rule);
    applyLimits();
    Q_EMIT limitsChanged();
    return {};
}

void LineService::applyLimits() {
    m_workspace.setSharedLimits(m_limits);
    for (const auto &[session, kept] : m_keptSessions)
        session->joints().setRules(m_limits);
}

void LineService::openLines(const model::WorkspaceFile &file) {
    m_workspace.open(file);
}

void LineService::closeLines() {
    m_workspace.close();
}

void LineService::keepLines() {
    m_keptLines.clear();
    if (!m_journal)
        return;
    for (int i = 0; i < m_workspace.count(); ++i) {
        model::Session &session = *m_workspace.session(i);
        m_keptLines.push_back(std::make_unique<journal::SessionJournal>(
            session, *m_journal, m_workspace.line(i).ownContext()));
        connect(&session.joints(), &model::JointWatcher::jointEnded, m_keptLines.back().get(),
                [this, i](const model::JointRecord &joint) { Q_EMIT jointEnded(i, joint); });
    }
}

void LineService::keep(model::Session &session) {
    if (!m_journal || m_keptSessions.count(&session))
        return;
    auto kept = std::make_unique<journal::SessionJournal>(session, *m_journal);
    // Sampled as every line of the service is (Workspace): the wire filled, so a joint's start is
    // timed as finely in the window as in the agent.
    session.scheduler().setFillWire(true);
    connect(&session.joints(), &model::JointWatcher::jointEnded, kept.get(),
            [this](const model::JointRecord &joint) { Q_EMIT jointEnded(-1, joint); });
    session.joints().setRules(m_limits);
    m_keptSessions.emplace(&session, std::move(kept));
}

void LineService::release(model::Session &session) {
    m_keptSessions.erase(&session);
}

bool LineService::finish(int ms) {
    const auto endJoints = [](model::Session &session) {
        for (model::DeviceModel *device : session.devices())
            session.joints().unwatch(device);
    };
    for (int i = 0; i < m_workspace.count(); ++i)
        endJoints(*m_workspace.session(i));
    for (const auto &[session, kept] : m_keptSessions)
        endJoints(*session);
    return !m_journal || m_journal->flush(ms);
}

} // namespace tipscope::service
