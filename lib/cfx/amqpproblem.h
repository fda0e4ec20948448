// What an AMQP error condition means for the person who set the endpoint up: one line, in the
// user's language, that says what to fix (the login, the host and port, the broker's AMQP 1.0
// plugin, the address, the certificates), with the broker's own words kept at the end.
#pragma once

#include <QString>

namespace tipscope::cfx {

// `name` and `description` are the AMQP error condition's; `address` the link's target.
[[nodiscard]] QString describeAmqpError(const QString &name, const QString &description,
                                        const QString &address);

} // namespace tipscope::cfx
