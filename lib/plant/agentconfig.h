// AgentConfig: what tipscope-agent (and `tipscope-cli monitor --mqtt`) is told to do, read from a
// versioned JSON file (docs/mqtt.md, "The agent's configuration"):
//     {"format": "tipscope-agent", "version": 1, "site": "plant-a", "workspace": "lines.json",
//      "journal": "/var/lib/tipscope/journal.sqlite", "broker": {"host": "mqtt.plant", ...},
//      "live": {"interval_ms": 1000, "batch_ms": 0}, "counters_interval_s": 600,
//      "remote_apply": false, "cfx": {"host": "mes.plant", "address": "/exchange/cfx", ...}}
//
// The optional "cfx" section publishes IPC-CFX over AMQP 1.0 besides MQTT (docs/cfx.md); its
// password comes from a file or an environment variable the same way.
// load() refuses a file that is not an agent configuration, one of a later version, a field of
// the wrong kind or out of range (naming the field), a workspace that cannot be read, and a
// password that cannot be read: everything is checked before anything connects, so SIGHUP with
// a bad file keeps the running configuration. The password comes from a file or an environment
// variable the configuration names, never from the file itself or a command line.
#pragma once

#include "cfx/cfxsettings.h"
#include "model/workspace/workspacefile.h"
#include "mqtt/mqttsettings.h"

#include "base/outcome.h"

#include <optional>

namespace tipscope::plant {

struct LiveSettings {
    int intervalMs = 1000; // at most one message per port per interval
    int batchMs = 0;       // > 0: the samples of this long go out together, as a list
};

struct AgentConfig {
    static constexpr int kVersion = 1;
    // The site is the first level of every topic and a field of every payload: a name people
    // read, not a document.
    static constexpr int kMaxSiteChars = 64;

    QString path; // the file read, for messages
    QString site = QStringLiteral("site");
    QString workspacePath;
    model::WorkspaceFile workspace;
    QString journalPath; // empty: the journal every TipScope program shares
    // The lines are published over MQTT ("broker", the local broker when left out); with
    // "broker": false they are not, and a "cfx" section must publish them. Journaled either way.
    bool mqtt = true;
    mqtt::MqttSettings broker;
    QString passwordSource; // "file /etc/tipscope/broker-password", for logs (never the value)
    LiveSettings live;
    int countersIntervalS = 600;
    bool remoteApply = false;
    std::optional<cfx::CfxSettings> cfx; // none: no CFX
    QString cfxPasswordSource;

    [[nodiscard]] static base::Outcome<AgentConfig> fromJson(const QJsonObject &json,
                                                             const QString &folder);
    [[nodiscard]] static base::Outcome<AgentConfig> load(const QString &path);
};

} // namespace tipscope::plant
