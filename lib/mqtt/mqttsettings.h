// What an MqttClient needs to reach a broker: address, identity, keep-alive, session, the
// credentials, TLS files, the last will and the protocol version, and the client's own bounds
// (how many messages it holds before they are written or acknowledged, how it backs off between
// attempts).
//
// The password is held in memory only. Callers read it with readSecretFile() or
// readSecretEnvironment() (mqttsecret.h), never from a command-line argument, and nothing logs it.
#pragma once

#include <QByteArray>
#include <QString>

namespace tipscope::mqtt {

enum class MqttProtocol { V311, V5 };

// Published by the broker when the connection ends without a DISCONNECT (a crash, kill -9, a
// network cut noticed after 1.5 x keep-alive). An empty topic sets no will.
struct MqttWill {
    QString topic;
    QByteArray payload;
    int qos = 1;
    bool retain = true;
};

// TLS is on when caFile is set. A client certificate needs both certFile and keyFile (the key
// unencrypted: nothing may prompt for a pass phrase). `insecure` skips the check that the
// broker's certificate names the host, for tests with a throwaway CA only.
struct MqttTls {
    QString caFile;
    QString certFile;
    QString keyFile;
    bool insecure = false;
};

struct MqttSettings {
    QString host = QStringLiteral("localhost");
    int port = 1883;
    // Empty: a random id. A persistent session (cleanSession false) needs a stable id to be
    // found again, so agents should set one.
    QString clientId;
    int keepAliveSeconds = 30;
    // False by default so the broker keeps the session (subscriptions, QoS 1 state) across
    // reconnects. With MQTT 5 the session still ends with the connection: libmosquitto's
    // non-blocking connect cannot send a session expiry interval.
    bool cleanSession = false;
    QString username;
    QByteArray password;
    MqttTls tls;
    MqttWill will;
    MqttProtocol protocol = MqttProtocol::V311;
    // Messages handed to libmosquitto and not yet done with (QoS 0 until written to the socket,
    // QoS 1 and 2 until acknowledged); publish() refuses more. This bounds libmosquitto's queues.
    int maxPendingMessages = 1000;
    // Back-off between connection attempts: the first wait, doubled after each failure up to
    // the maximum, back to the first after a successful connection.
    int retryMinMs = 1000;
    int retryMaxMs = 30000;
};

} // namespace tipscope::mqtt
