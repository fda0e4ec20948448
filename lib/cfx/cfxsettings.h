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

// RabbitMQ's AMQP 1.0 addresses, with their leading slash: /exchange/NAME, /exchange/NAME/KEY,
// /queue/NAME (and /topic/NAME). Every front end checks an address with these before it connects.
[[nodiscard]] bool isBrokerAddress(const QString &address);
// A queue, the only address requests can be taken from: an exchange keeps nothing for a reader.
[[nodiscard]] bool isRequestQueue(const QString &address);

} // namespace tipscope::cfx
