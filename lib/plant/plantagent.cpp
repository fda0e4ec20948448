#include "plantagent.h"

#include "mqtt/mqttclient.h"
#ifdef TIPSCOPE_WITH_CFX
#include "cfx/cfxmessages.h"
#include "cfx/cfxpublisher.h"
#include "journal/jointexport.h"
#include "model/device/stationmodel.h"
#endif

#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcAgent, "tipscope.agent")

namespace tipscope::plant {

namespace {
// The demo line of a workspace plays a station at work, so joints come without hardware.
model::WorkspaceFile withDemoActivity(model::WorkspaceFile file) {
    for (model::WorkspaceLine &line : file.lines)
        if (line.session.line.kind == link::LineSettings::Kind::Demo)
            line.session.demoActivity = true;
    return file;
}
} // namespace

PlantAgent::PlantAgent(Publisher who, QObject *parent)
    : QObject(parent)
    , m_who(std::move(who)) {
    connect(&m_lines.workspace(), &model::Workspace::lineStateChanged, this,
            &PlantAgent::onLineState);
}

PlantAgent::~PlantAgent() {
    m_cfx.reset();
    m_publisher.reset();
    m_lines.closeLines();
}

void PlantAgent::start(const AgentConfig &config) {
    m_config = config;
    service::LineService::Options options;
    options.journalPath = config.journalPath;
    if (const auto limits = m_lines.start(options); !limits)
        qCWarning(lcAgent, "%s; the default limits judge joints", qPrintable(limits.error()));
    journal::Journal &journal = m_lines.journal();
    qCInfo(lcAgent, "journal %s", qPrintable(journal.path()));
    connect(&journal, &journal::Journal::stateChanged, this, [this](journal::JournalState state) {
        const journal::Journal &j = m_lines.journal();
        if (state == journal::JournalState::Failed && !journal::isPassing(j.problem()))
            return failJournal(j.errorText());
        if (state == journal::JournalState::Failed)
            qCCritical(lcAgent, "the journal cannot be written: %s; its records wait in memory",
                       qPrintable(j.errorText()));
        else if (state == journal::JournalState::Ready)
            qCInfo(lcAgent, "the journal is written");
    });
    connect(&journal, &journal::Journal::recordsLost, this,
            [](qint64 total, const QString &reason) {
                qCCritical(lcAgent, "%lld records lost: %s", total, qPrintable(reason));
            });
    openLines();
    startMqtt();
    startCfx();
}

void PlantAgent::startMqtt() {
    if (!m_config.mqtt) {
        m_publisher.reset();
        return;
    }
    if (!m_publisher) {
        m_publisher = std::make_unique<PlantPublisher>(m_lines.workspace(), m_lines.journal());
        connect(m_publisher.get(), &PlantPublisher::stopped, this, [this] {
            m_mqttStopped = true;
            finishIfStopped();
        });
    }
    m_publisher->start(m_config, m_who);
    watchClient();
}

void PlantAgent::finishIfStopped() {
    if (!m_stopping || !m_mqttStopped || m_cfx || std::exchange(m_finished, true))
        return;
    if (!m_lines.finish(10000))
        qCCritical(lcAgent, "the journal could not write everything before stopping");
    Q_EMIT finished();
}

#ifdef TIPSCOPE_WITH_CFX
void PlantAgent::startCfx() {
    m_cfx.reset();
    if (!m_config.cfx)
        return;
    m_cfx = std::make_unique<cfx::CfxPublisher>(
        m_lines.journal(), *m_config.cfx,
        [this](const model::DeviceIdentity &device) { return cfxHandleOf(device); },
        [this] { return cfxEndpoints(); },
        cfx::CfxForwarder::Boards{[this] { return boardStations(); },
                                  [this] { return boardStationsKnown(); },
                                  [this](const model::DeviceIdentity &station, qint64 timeMs) {
                                      return stationSettled(station, timeMs);
                                  }});
    connect(m_cfx.get(), &cfx::CfxPublisher::stopped, this, [this] {
        m_cfx.release()->deleteLater(); // its own signal is still being emitted
        finishIfStopped();
    });
    watchCfx();
    connect(&m_lines.workspace(), &model::Workspace::lineDevicesChanged, m_cfx.get(),
            &cfx::CfxPublisher::stationsChanged);
    connect(&m_lines.workspace(), &model::Workspace::lineDevicesChanged, this,
            &PlantAgent::watchCfxStations);
    watchCfxStations();
    m_cfx->start();
}

void PlantAgent::watchCfxStations() {
    if (!m_cfx)
        return;
    model::Workspace &workspace = m_lines.workspace();
    for (int i = 0; i < workspace.count(); ++i)
        for (model::DeviceModel *device : workspace.session(i)->devices())
            if (auto *station = qobject_cast<model::StationModel *>(device))
                m_cfx->watchStation(*station, cfxHandleOf(station->identity()));
}

void PlantAgent::watchCfx() {
    cfx::AmqpSender &sender = m_cfx->sender();
    connect(&sender, &cfx::AmqpSender::connected, this, [this, &sender] {
        m_cfxTrouble = false;
        qCInfo(lcAgent, "CFX: connected to %s", qPrintable(sender.where()));
    });
    // Each failed attempt says the same: said once, until it connects again.
    connect(&sender, &cfx::AmqpSender::problem, this, [this, &sender](const QString &text) {
        if (!std::exchange(m_cfxTrouble, true))
            qCWarning(lcAgent,
                      "CFX: %s: %s; the lines are polled and journaled meanwhile, and faults "
                      "are sent once the broker takes them",
                      qPrintable(sender.where()), qPrintable(text));
    });
    connect(&m_cfx->forwarder(), &cfx::CfxForwarder::problemChanged, this,
            [](const QString &problem) {
                if (!problem.isEmpty())
                    qCWarning(lcAgent, "CFX: cannot read the journal to forward it: %s",
                              qPrintable(problem));
            });
}

QString PlantAgent::cfxHandleOf(const model::DeviceIdentity &device) {
    // The workspace line's name where the device is reached, else how it is reached.
    const model::Workspace &workspace = m_lines.workspace();
    const int index = workspace.lineOf(device);
    const QString line = index >= 0 ? workspace.line(index).name : device.line;
    return cfx::endpointHandle(m_config.cfx->vendor, device.model,
                               QStringLiteral("%1-%2").arg(line).arg(device.address.value_or(0)));
}

QList<model::DeviceIdentity> PlantAgent::boardStations() {
    // The soldering stations of the lines without a work context of their own; a feeder makes
    // no joints.
    QList<model::DeviceIdentity> stations;
    model::Workspace &workspace = m_lines.workspace();
    for (int i = 0; i < workspace.count(); ++i)
        if (!workspace.line(i).ownContext())
            for (const model::DeviceModel *device : workspace.session(i)->devices())
                if (qobject_cast<const model::StationModel *>(device))
                    stations.append(device->identity());
    return stations;
}

bool PlantAgent::boardStationsKnown() {
    model::Workspace &workspace = m_lines.workspace();
    for (int i = 0; i < workspace.count(); ++i) {
        if (workspace.line(i).ownContext())
            continue;
        model::Session *session = workspace.session(i);
        // A line that has not found its stations yet (just started, or reconnecting) would
        // leave them out of the board.
        if (!session || session->devices().isEmpty())
            return false;
    }
    return true;
}

bool PlantAgent::stationSettled(const model::DeviceIdentity &station, qint64 timeMs) {
    model::Workspace &workspace = m_lines.workspace();
    bool everyLineFound = true;
    for (int i = 0; i < workspace.count(); ++i) {
        model::Session *session = workspace.session(i);
        if (!session || session->devices().isEmpty()) {
            everyLineFound = false;
            continue;
        }
        for (const model::DeviceModel *device : session->devices())
            if (device->identity() == station)
                return session->joints().settledUntil(timeMs, station);
    }
    // Gone from every line: nothing of it is still to come, unless its line is finding it again.
    return everyLineFound;
}

QList<cfx::EndpointIdentity> PlantAgent::cfxEndpoints() {
    QList<cfx::EndpointIdentity> endpoints;
    model::Workspace &workspace = m_lines.workspace();
    for (int i = 0; i < workspace.count(); ++i)
        for (const model::DeviceModel *device : workspace.session(i)->devices()) {
            const model::DeviceIdentity identity = device->identity();
            endpoints.append({cfxHandleOf(identity), m_config.cfx->vendor, identity.model,
                              QStringLiteral("%1 %2").arg(workspace.line(i).name,
                                                          journal::addressText(identity)),
                              identity.softwareVersion});
        }
    return endpoints;
}
#else
void PlantAgent::startCfx() {
    if (m_config.cfx)
        qCWarning(lcAgent, "this TipScope was built without Qpid Proton: the \"cfx\" section "
                           "is not published");
}
#endif

void PlantAgent::reload(const AgentConfig &config) {
    if (config.journalPath != m_config.journalPath)
        qCWarning(lcAgent, "the journal stays %s until the agent restarts",
                  qPrintable(m_lines.journal().path()));
    const bool linesChanged =
        config.workspace.toJson() != m_config.workspace.toJson() || config.site != m_config.site;
    const QString journalPath = m_config.journalPath;
    m_config = config;
    m_config.journalPath = journalPath;
    if (linesChanged)
        openLines();
    startMqtt();
    startCfx();
    qCInfo(lcAgent, "configuration %s applied%s", qPrintable(config.path),
           linesChanged ? ", lines opened again" : "");
}

void PlantAgent::failJournal(const QString &why) {
    if (!m_failure.isEmpty())
        return;
    m_failure = why;
    qCCritical(lcAgent,
               "the journal cannot be used: %s; the agent stops, since no joint or event "
               "it measures could be kept",
               qPrintable(why));
    stop();
}

void PlantAgent::stop() {
    if (m_stopping)
        return;
    m_stopping = true;
    qCInfo(lcAgent, "stopping: every device goes offline");
#ifdef TIPSCOPE_WITH_CFX
    if (m_cfx)
        m_cfx->stop();
#endif
    if (m_publisher)
        m_publisher->stop();
    else
        m_mqttStopped = true;
    finishIfStopped();
}

void PlantAgent::openLines() {
    m_lines.openLines(withDemoActivity(m_config.workspace));
}

void PlantAgent::watchClient() {
    mqtt::MqttClient *client = m_publisher->client();
    const QString where =
        QStringLiteral("%1:%2").arg(m_config.broker.host).arg(m_config.broker.port);
    connect(client, &mqtt::MqttClient::connected, this,
            [where] { qCInfo(lcAgent, "connected to the broker %s", qPrintable(where)); });
    // The client itself logs each failed attempt; said here once, until it connects again.
    connect(client, &mqtt::MqttClient::problemOccurred, this, [this] {
        if (!std::exchange(m_brokerTrouble, true))
            qCWarning(lcAgent, "the lines are polled and journaled meanwhile; joints and events "
                               "are forwarded once the broker takes them");
    });
    connect(client, &mqtt::MqttClient::connected, this, [this] { m_brokerTrouble = false; });
    connect(m_publisher->forwarder(), &JournalForwarder::problemChanged, this,
            [](const QString &problem) {
                if (!problem.isEmpty())
                    qCWarning(lcAgent, "cannot read the journal to forward it: %s",
                              qPrintable(problem));
            });
}

void PlantAgent::onLineState(int index, model::Session::State state, const QString &text) {
    const QString line = m_lines.workspace().line(index).name;
    if (state == model::Session::State::Connected)
        qCInfo(lcAgent, "line %s: %s", qPrintable(line), qPrintable(text));
    else if (state == model::Session::State::Retrying || state == model::Session::State::Failed)
        qCWarning(lcAgent, "line %s: %s", qPrintable(line), qPrintable(text));
}

} // namespace tipscope::plant
