#include "linklogging.h"

namespace tipscope::link {

// Debug is below the default level: nothing is printed unless a rule switches it on.
Q_LOGGING_CATEGORY(lcLink, "tipscope.link", QtInfoMsg)
Q_LOGGING_CATEGORY(lcLinkHex, "tipscope.link.hex", QtWarningMsg)

} // namespace tipscope::link
