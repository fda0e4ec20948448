#include "mqttcallbacks.h"

#include <QLoggingCategory>
#include <mosquitto.h>

namespace tipscope::mqtt {

Q_LOGGING_CATEGORY(lcMqttLibrary, "tipscope.mqtt.library", QtWarningMsg)

namespace {

// What a subscription's granted QoS is when the broker refused it.
constexpr int kSubscriptionRefused = 0x80;

MqttClient *owner(void *userData) {
    return static_cast<MqttClient *>(userData);
}

} // namespace

void MqttCallbacks::push(void *userData, MqttClient::Event event) {
    owner(userData)->m_events.push_back(std::move(event));
}

void MqttCallbacks::install(mosquitto *client) {
    using Kind = MqttClient::Event::Kind;
    mosquitto_connect_callback_set(client, [](mosquitto *, void *data, int code) {
        push(data, {Kind::Connack, code});
    });
    mosquitto_disconnect_callback_set(client, [](mosquitto *, void *data, int rc) {
        push(data, {Kind::Disconnect, rc});
    });
    mosquitto_publish_v5_callback_set(
        client, [](mosquitto *, void *data, int mid, int reason, const mosquitto_property *) {
            push(data, {Kind::Published, reason, mid});
        });
    mosquitto_subscribe_callback_set(
        client, [](mosquitto *, void *data, int mid, int count, const int *granted) {
            const bool refused = count < 1 || granted[0] >= kSubscriptionRefused;
            push(data, {Kind::Subscribed, refused ? kSubscriptionRefused : 0, mid});
        });
    mosquitto_message_callback_set(
        client, [](mosquitto *, void *data, const mosquitto_message *message) {
            const char *bytes = static_cast<const char *>(message->payload);
            push(data, {QString::fromUtf8(message->topic), QByteArray(bytes, message->payloadlen),
                        message->retain});
        });
    mosquitto_log_callback_set(client, [](mosquitto *, void *data, int level, const char *text) {
        // It logs every packet: not worth a string unless someone reads it.
        if (level != MOSQ_LOG_ERR && !lcMqttLibrary().isDebugEnabled())
            return;
        const QString line = QString::fromUtf8(text);
        qCDebug(lcMqttLibrary).noquote() << line;
        // libmosquitto logs OpenSSL's reason for a failed handshake and returns only MOSQ_ERR_TLS.
        if (level == MOSQ_LOG_ERR && line.contains(QLatin1String("OpenSSL")))
            owner(data)->m_tlsDetail = line;
    });
}

} // namespace tipscope::mqtt
