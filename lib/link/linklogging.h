// The link layer's logging categories, switchable with QT_LOGGING_RULES (docs/architecture.md).
//
// tipscope.link: the line's states, reconnects, timeouts and retries. tipscope.link.hex: every
// byte sent and received, in hex. Both log at debug level, which is off by default, so a front
// end's standard error stays quiet until someone asks, e.g.
// QT_LOGGING_RULES="tipscope.link.debug=true;tipscope.link.hex.debug=true".
#pragma once

#include <QLoggingCategory>

namespace tipscope::link {

Q_DECLARE_LOGGING_CATEGORY(lcLink)
Q_DECLARE_LOGGING_CATEGORY(lcLinkHex)

} // namespace tipscope::link
