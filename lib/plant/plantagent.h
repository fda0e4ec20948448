// PlantAgent: the line service without a screen, shared by tipscope-agent and `tipscope-cli
// monitor --mqtt`. It opens the configuration's workspace through the LineService (every line
// polled live, each with its own request queue and reconnection, its joints and events kept in
// the journal and judged by the shared joint limits, as in every front end) and publishes the
// lines to the MQTT broker (PlantPublisher) with store and forward from the journal. With a "cfx"
// section it also makes every station an IPC-CFX endpoint (cfx/cfxpublisher.h, docs/cfx.md);
// with "broker": false that is all it publishes.
// The demo line of a workspace solders and rests, so the agent can be tried without a station.
//
// reload() applies a new configuration: the lines are opened again only when the workspace
// changed, the broker clients are always made anew; the journal stays the one opened first (a
// new path needs a restart, and reload() says so). stop() publishes every device offline, waits
// for the journal to write what it holds, and emits finished(). What happens is said through the
// logging category tipscope.agent (lines up and down, the broker connected or why not, the
// backlog forwarded), for the program to print; the password never appears in it.
//
// A journal that waiting cannot mend (damaged, another program's file, a newer schema, a folder
// or file that cannot be written) stops the agent, offline first, with failure() saying why:
// running on would publish live values while every joint is lost, and look healthy. A journal
// that is locked or full holds its records in memory and is tried again (journal.h).
#pragma once

#include "agentconfig.h"
#include "plantpublisher.h"

#include "service/lineservice.h"

#include <QObject>
#include <memory>

namespace tipscope::cfx {
class CfxPublisher;
struct EndpointIdentity;
} // namespace tipscope::cfx
#include <vector>

namespace tipscope::plant {

class PlantAgent : public QObject {
    Q_OBJECT
public:
    // `who` names the program in every device's status.
    explicit PlantAgent(Publisher who, QObject *parent = nullptr);
    ~PlantAgent() override;

    // Opens the journal and the lines and starts publishing.
    void start(const AgentConfig &config);
    void reload(const AgentConfig &config);
    void stop();

    [[nodiscard]] model::Workspace &workspace() { return m_lines.workspace(); }
    [[nodiscard]] journal::Journal *journal() {
        return m_lines.isStarted() ? &m_lines.journal() : nullptr;
    }
    // Null when the configuration publishes nothing over MQTT ("broker": false).
    [[nodiscard]] PlantPublisher *publisher() const { return m_publisher.get(); }
    // Null without a "cfx" section (or without Qpid Proton in this build).
    [[nodiscard]] cfx::CfxPublisher *cfxPublisher() const { return m_cfx.get(); }
    [[nodiscard]] const AgentConfig &config() const { return m_config; }
    // Why the agent stopped by itself (its journal cannot be used); empty otherwise.
    [[nodiscard]] QString failure() const { return m_failure; }

Q_SIGNALS:
    void finished();

private:
    // Publishes over MQTT as the configuration says, or stops publishing there (CFX only).
    void startMqtt();
    void openLines();
    void watchClient();
    void onLineState(int index, model::Session::State state, const QString &text);
    void failJournal(const QString &why);
    void startCfx();
    void watchCfx();
    void watchCfxStations();
    // A station's CFX handle: vendor, model, and the workspace line's name with its address
    // (TipScope does not read a station's serial number today).
    [[nodiscard]] QString cfxHandleOf(const model::DeviceIdentity &device);
    [[nodiscard]] QList<cfx::EndpointIdentity> cfxEndpoints();
    [[nodiscard]] QList<model::DeviceIdentity> boardStations();
    // Every line that follows the shared work context has found its stations.
    [[nodiscard]] bool boardStationsKnown();
    // `station` has ended every joint it began before `timeMs`; a station no line has now, once
    // every line has found its stations (its own may be finding it again).
    [[nodiscard]] bool stationSettled(const model::DeviceIdentity &station, qint64 timeMs);
    void finishIfStopped();

    Publisher m_who;
    AgentConfig m_config;
    service::LineService m_lines;
    std::unique_ptr<PlantPublisher> m_publisher;
    std::unique_ptr<cfx::CfxPublisher> m_cfx;
    bool m_mqttStopped = false;
    bool m_finished = false; // finished() was emitted
    bool m_cfxTrouble = false;
    bool m_stopping = false;
    bool m_brokerTrouble = false;
    QString m_failure;
};

} // namespace tipscope::plant
