// tipscope-bench mqtt: what the MQTT client costs against a local Mosquitto. Its CPU share and
// context switches while connected and idle (the event-loop integration must not poll), and
// QoS 1 messages a second from publish() to the broker's PUBACK and to a subscribing client.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runMqttBench(const QStringList &args);

} // namespace tipscope::bench
