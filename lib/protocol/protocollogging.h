// The protocol layer's logging category, tipscope.protocol: every malformed frame the decoder
// counts and skips, with why and its bytes. Debug level, off by default; switched on with
// QT_LOGGING_RULES="tipscope.protocol.debug=true" (docs/architecture.md).
#pragma once

#include <QLoggingCategory>

namespace tipscope::protocol {

Q_DECLARE_LOGGING_CATEGORY(lcProtocol)

} // namespace tipscope::protocol
