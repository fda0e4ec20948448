#include "mqttproblem.h"

#include <QCoreApplication>
#include <cerrno>
#include <cstring>
#include <mosquitto.h>

namespace tipscope::mqtt {

namespace {

struct MqttProblemTr {
    Q_DECLARE_TR_FUNCTIONS(MqttClient)
};

// MQTT 5 reason codes of a refused CONNACK (MQTT 5.0, 3.2.2.2).
constexpr int kV5BadCredentials = 134;
constexpr int kV5NotAuthorised = 135;
constexpr int kV5ServerUnavailable = 136;
constexpr int kV5ServerBusy = 137;
constexpr int kV5Banned = 138;
constexpr int kV5UnsupportedProtocol = 132;
constexpr int kV5InvalidClientId = 133;

MqttProblemReport credentials(const QString &where) {
    return {MqttProblem::BadCredentials,
            MqttProblemTr::tr("The broker %1 refused the connection: bad user name or password.")
                .arg(where)};
}

MqttProblemReport notAuthorised(const QString &where) {
    return {MqttProblem::NotAuthorised,
            MqttProblemTr::tr(
                "The broker %1 refused the connection: not authorised (wrong user name or "
                "password, or this user may not connect).")
                .arg(where)};
}

MqttProblemReport refused(const QString &where, const QString &why) {
    return {MqttProblem::Refused,
            MqttProblemTr::tr("The broker %1 refused the connection: %2.").arg(where, why)};
}

MqttProblemReport describeV311(int code, const QString &where) {
    switch (code) {
    case 1:
        return refused(where, MqttProblemTr::tr("it does not speak MQTT 3.1.1"));
    case 2:
        return refused(where, MqttProblemTr::tr("it does not accept this client id"));
    case 3:
        return refused(where, MqttProblemTr::tr("the service is unavailable"));
    case 4:
        return credentials(where);
    case 5:
        return notAuthorised(where);
    default:
        return refused(where, MqttProblemTr::tr("return code %1").arg(code));
    }
}

MqttProblemReport describeV5(int code, const QString &where) {
    switch (code) {
    case kV5BadCredentials:
        return credentials(where);
    case kV5NotAuthorised:
    case kV5Banned:
        return notAuthorised(where);
    case kV5UnsupportedProtocol:
        return refused(where, MqttProblemTr::tr("it does not speak MQTT 5"));
    case kV5InvalidClientId:
        return refused(where, MqttProblemTr::tr("it does not accept this client id"));
    case kV5ServerUnavailable:
    case kV5ServerBusy:
        return refused(where, MqttProblemTr::tr("the service is unavailable"));
    default:
        return refused(where, MqttProblemTr::tr("reason code %1").arg(code));
    }
}

MqttProblemReport describeErrno(int errnoValue, const QString &where) {
    const QString why = QString::fromLocal8Bit(std::strerror(errnoValue));
    switch (errnoValue) {
    case ECONNREFUSED:
        return {MqttProblem::Unreachable,
                MqttProblemTr::tr("No MQTT broker accepts connections at %1 (connection refused).")
                    .arg(where)};
    case ECONNRESET:
    case EPIPE:
        return {MqttProblem::ConnectionLost,
                MqttProblemTr::tr("The broker %1 closed the connection (%2).").arg(where, why)};
    default:
        return {MqttProblem::Unreachable,
                MqttProblemTr::tr("The broker %1 cannot be reached: %2.").arg(where, why)};
    }
}

} // namespace

MqttProblemReport describeConnack(int code, MqttProtocol protocol, const QString &where) {
    return protocol == MqttProtocol::V5 ? describeV5(code, where) : describeV311(code, where);
}

MqttProblemReport describeLibraryError(int rc, int errnoValue, const QString &where,
                                       const QString &detail) {
    switch (rc) {
    case MOSQ_ERR_SUCCESS:
        return {};
    case MOSQ_ERR_ERRNO:
        // libmosquitto sets EPROTO when OpenSSL failed, whether or not OpenSSL said why.
        return errnoValue == EPROTO ? describeLibraryError(MOSQ_ERR_TLS, 0, where, detail)
                                    : describeErrno(errnoValue, where);
    case MOSQ_ERR_EAI:
        return {MqttProblem::HostNotFound,
                MqttProblemTr::tr("The broker's address %1 cannot be resolved.").arg(where)};
    case MOSQ_ERR_TLS:
        return {MqttProblem::TlsFailure,
                detail.isEmpty()
                    ? MqttProblemTr::tr("The TLS handshake with the broker %1 failed.").arg(where)
                    : MqttProblemTr::tr("The TLS handshake with the broker %1 failed: %2")
                          .arg(where, detail)};
    case MOSQ_ERR_KEEPALIVE:
        return {MqttProblem::ConnectionLost,
                MqttProblemTr::tr("The broker %1 stopped answering within the keep-alive time.")
                    .arg(where)};
    case MOSQ_ERR_CONN_LOST:
    case MOSQ_ERR_NO_CONN:
        return {MqttProblem::ConnectionLost,
                MqttProblemTr::tr("The connection to the broker %1 was lost.").arg(where)};
    case MOSQ_ERR_PROTOCOL:
    case MOSQ_ERR_MALFORMED_PACKET:
        return {MqttProblem::ProtocolError,
                MqttProblemTr::tr("The broker %1 sent data that is not valid MQTT.").arg(where)};
    default:
        return {MqttProblem::ConnectionLost,
                MqttProblemTr::tr("The connection to the broker %1 failed: %2.")
                    .arg(where, QString::fromUtf8(mosquitto_strerror(rc)))};
    }
}

MqttProblemReport describeHangUp(const QString &where) {
    return {
        MqttProblem::Unreachable,
        MqttProblemTr::tr("The broker %1 cannot be reached: the connection was refused or reset.")
            .arg(where)};
}

MqttProblemReport describeLookupFailure(const QString &host, const QString &detail) {
    return {
        MqttProblem::HostNotFound,
        MqttProblemTr::tr("The broker's host name %1 cannot be resolved: %2").arg(host, detail)};
}

} // namespace tipscope::mqtt
