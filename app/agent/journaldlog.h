// Log lines for journald: each message on standard error with the syslog priority prefix systemd
// reads (`<3>` error ... `<7>` debug, SyslogLevelPrefix=), so `journalctl -u tipscope-agent -p
// warning` finds the warnings. A message of several lines gets the prefix on each line. The
// category is named only for debug messages, where it says which part spoke.
#pragma once

namespace tipscope::agent {

void installJournaldLog();

} // namespace tipscope::agent
