// libmosquitto's callbacks for an MqttClient. They run inside libmosquitto's calls, where the
// client must not re-enter it, stop or emit (a slot could do anything): each one only records
// an Event, and the client handles the events once the call has returned.
#pragma once

#include "mqttclient.h"

#include <QByteArray>
#include <QString>

struct mosquitto;

namespace tipscope::mqtt {

struct MqttClient::Event {
    enum class Kind { Connack, Disconnect, Published, Subscribed, Message };
    Event(Kind kind, int code, int messageId = 0)
        : kind(kind)
        , code(code)
        , messageId(messageId) {}
    Event(QString topic, QByteArray payload, bool retained)
        : kind(Kind::Message)
        , topic(std::move(topic))
        , payload(std::move(payload))
        , retained(retained) {}

    Kind kind;
    int code = 0; // CONNACK code, disconnect rc, PUBACK reason, granted QoS
    int messageId = 0;
    QString topic;
    QByteArray payload;
    bool retained = false;
};

struct MqttCallbacks {
    static void install(mosquitto *client);

private:
    static void push(void *userData, MqttClient::Event event);
};

} // namespace tipscope::mqtt
