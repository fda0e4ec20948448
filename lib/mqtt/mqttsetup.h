// Creating one libmosquitto client from MqttSettings: the library initialised once per process,
// then id, session, protocol version, credentials, will and TLS applied in that order. A
// setting the library refuses comes back as a sentence naming it (never the password).
#pragma once

#include "mqttsettings.h"

#include "base/outcome.h"

#include <QString>
#include <memory>

struct mosquitto;

namespace tipscope::mqtt {

struct MosquittoDeleter {
    void operator()(mosquitto *client) const;
};
using MosquittoHandle = std::unique_ptr<mosquitto, MosquittoDeleter>;

// The client, or why a setting is refused. `userData` is what callbacks receive.
[[nodiscard]] base::Outcome<MosquittoHandle> createMosquitto(const MqttSettings &settings,
                                                             void *userData);

// Empty (success) without TLS; otherwise whether the TLS files can be used: the CA file readable
// and PEM, a client certificate with its key, each readable. Checked at every connection, and by
// `tipscope-agent --check`, so that a bad file is found before the service runs.
[[nodiscard]] base::Outcome<void> checkTlsFiles(const MqttTls &tls);

// The client id to use: `settings.clientId`, or a new random one when it is empty.
[[nodiscard]] QString effectiveClientId(const MqttSettings &settings);

} // namespace tipscope::mqtt
