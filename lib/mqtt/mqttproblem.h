// Why an MqttClient is not connected, as a kind the agent and the GUI can act on and as a
// sentence for people (in the user's language, naming the broker, never a password).
//
// Codes come from three places: libmosquitto's return codes (with errno for socket errors),
// the broker's CONNACK (MQTT 3.1.1 return codes 1-5, MQTT 5 reason codes 128 and above), and
// what libmosquitto logged about a TLS failure (OpenSSL's own words, passed in as `detail`).
#pragma once

#include "mqttsettings.h"

#include <QString>

namespace tipscope::mqtt {

enum class MqttProblem {
    None,
    InvalidSettings, // a file that cannot be read, an id or will the library refuses
    HostNotFound,    // the host name does not resolve
    Unreachable,     // nothing accepts the connection, or the network has no route
    ConnectionLost,  // the broker closed the connection, or stopped answering
    TlsFailure,      // the handshake failed: certificate, CA, protocol
    BadCredentials,  // the broker refused the user name or password
    NotAuthorised,   // the broker refused this client (credentials or ACL)
    Refused,         // any other CONNACK refusal (protocol version, client id, busy)
    ProtocolError,   // the broker sent something libmosquitto does not understand
};

struct MqttProblemReport {
    MqttProblem problem = MqttProblem::None;
    QString text;
};

// `where` is "host:port" as people should read it.
[[nodiscard]] MqttProblemReport describeConnack(int code, MqttProtocol protocol,
                                                const QString &where);
// `errnoValue` matters for MOSQ_ERR_ERRNO; `detail` for MOSQ_ERR_TLS (may be empty).
[[nodiscard]] MqttProblemReport describeLibraryError(int rc, int errnoValue, const QString &where,
                                                     const QString &detail);
// A connection that was refused or reset before the broker answered (during the TLS handshake).
[[nodiscard]] MqttProblemReport describeHangUp(const QString &where);
[[nodiscard]] MqttProblemReport describeLookupFailure(const QString &host, const QString &detail);

} // namespace tipscope::mqtt
