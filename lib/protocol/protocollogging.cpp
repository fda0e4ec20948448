#include "protocollogging.h"

namespace tipscope::protocol {

// Debug is below the default level: nothing is printed unless a rule switches it on.
Q_LOGGING_CATEGORY(lcProtocol, "tipscope.protocol", QtInfoMsg)

} // namespace tipscope::protocol
