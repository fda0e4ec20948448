#include "climonitorjoints.h"

#include "clicommands.h"

#include "link/line.h"

#include <QDateTime>

namespace tipscope::cli {

namespace {
struct MonitorJointsTr {
    Q_DECLARE_TR_FUNCTIONS(CliMonitor)
};
constexpr int kFinishMs = 10'000;
} // namespace

MonitorJoints::MonitorJoints(CliSession &s, const link::DeviceInfo &device, int ports,
                             model::JointLimitRules rules)
    : m_session(s)
    , m_rules(std::move(rules))
    , m_lastMs(size_t(ports), 0)
    , m_journal(journalPathOf(s.options())) {
    const model::DeviceIdentity identity{link::lineIdentityName(s.options().line), device.address,
                                         device.model, device.softwareVersion};
    for (int p = 1; p <= ports; ++p)
        m_detectors.emplace_back(identity, p);
    QObject::connect(&m_journal, &journal::Journal::stateChanged, &m_journal,
                     [this](journal::JournalState state) {
                         if (state == journal::JournalState::Failed)
                             m_session.err() << "# " << m_journal.errorText() << Qt::endl;
                     });
    if (s.options().lineContext) {
        m_journal.setContext(*s.options().lineContext);
        return;
    }
    m_context = std::make_unique<journal::WorkContextFollower>(
        m_journal, journal::workContextPathFor(m_journal.path()));
    QObject::connect(m_context.get(), &journal::WorkContextFollower::unreadable, &m_journal,
                     [this](const QString &why) { m_session.err() << "# " << why << Qt::endl; });
}

void MonitorJoints::add(int port, const model::PortReading &reading) {
    model::JointDetector &detector = m_detectors.at(size_t(port - 1));
    detector.setLimits(m_rules.limitsFor(port, reading.tool));
    m_lastMs[size_t(port - 1)] = reading.timeMs;
    report(detector.add(reading));
}

void MonitorJoints::gap(int port, qint64 timeMs) {
    report(m_detectors.at(size_t(port - 1)).gap(timeMs));
}

bool MonitorJoints::finish() {
    for (size_t i = 0; i < m_detectors.size(); ++i)
        report(m_detectors[i].gap(m_lastMs[i]));
    if (m_journal.flush(kFinishMs))
        return true;
    m_session.err() << "# "
                    << MonitorJointsTr::tr("%1 records could not be kept in the journal %2: %3")
                           .arg(m_journal.pendingCount() + m_journal.lostCount())
                           .arg(m_journal.path(), m_journal.errorText())
                    << Qt::endl;
    return false;
}

void MonitorJoints::report(const std::optional<model::JointRecord> &joint) {
    if (!joint)
        return;
    m_session.out() << monitorJointLine(*joint) << Qt::endl;
    m_journal.append(*joint);
}

QString monitorJointLine(const model::JointRecord &j) {
    return QStringLiteral("%1  joint P%2 %3 %4 °C lowest %5 °C dip %6 K recovery %7 %8")
        .arg(QDateTime::fromMSecsSinceEpoch(j.startMs).toString(Qt::ISODateWithMs))
        .arg(j.port)
        .arg(j.tool.isEmpty() ? QStringLiteral("-") : j.tool)
        .arg(j.setpoint)
        .arg(j.lowestTip)
        .arg(j.dipDepth)
        .arg(j.recoveryMs
                 ? QString::number(double(*j.recoveryMs) / 1000, 'f', 2) + QStringLiteral(" s")
                 : QStringLiteral("-"))
        .arg(model::jointVerdictName(j.verdict));
}

} // namespace tipscope::cli
