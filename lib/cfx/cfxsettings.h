// What a CFX endpoint is told (the agent configuration's "cfx" section, docs/cfx.md): the
// broker and its link, how messages are encoded, how often a heartbeat goes, and the vendor part
// of each station's handle. A plain value; reading and checking it is AgentConfig's.
#pragma once

#include "cfxenvelope.h"

#include <QByteArray>
#include <QString>

namespace tipscope::cfx {

struct CfxSettings {
    QString host;
    int port = 5672;
    bool tls = false;
    QString caFile;
    QString certFile;
    QString keyFile;
    QString username; // empty: anonymous
    QByteArray password;
    QString address = QStringLiteral("/exchange/amq.topic"); // RabbitMQ's form, with its slash
    // Where requests to the endpoints arrive (a queue of the broker's); empty: none are served.
    QString requestAddress;
    Codec codec = Codec::Gzip; // the SDK's endpoint compresses by default
    int heartbeatS = 60;       // CFX asks for one at least every 5 minutes
    int retryMaxS = 60;
    QString vendor = QStringLiteral("JBC");
};

} // namespace tipscope::cfx
