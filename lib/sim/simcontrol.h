// SimControl: the text commands that steer a running simulator (tipscope-sim reads them from
// its standard input; tests and the demo call execute() directly).
//
//   port-error PORT CODE    station-error CODE     tool PORT TOOL       alarm PORT FLAGS
//   status PORT STATUS      robot-mode on|off      fuse on|off          feeder-error CODE
//   drop SHARE   corrupt SHARE   garbage SHARE   bad-data SHARE   drop-requests SHARE
//   corrupt-requests SHARE   nak CODE [all|writes|COMMAND]   latency MS   pace BAUD
//   joint PORT DEPTH RECOVERY_MS   wear PORT SHARE
//   get [CODE...]           stats                  help
// One table holds them: what help lists is what is accepted (simCommandUsage() adds a front
// end's own commands, such as tipscope-sim's unplug and plug).
// execute() returns the reply line; an unknown or malformed command gets a reply that starts
// with "error:" and changes nothing.
#pragma once

#include "simline.h"

#include <QString>

namespace tipscope::sim {

[[nodiscard]] QString executeSimCommand(SimLine &line, const QString &command);
// "commands: port-error PORT CODE | … | help", then `more` (a front end's own commands).
[[nodiscard]] QString simCommandUsage(const QStringList &more);
// What a NAK fault applies to: "all", "writes" or a command ("ST1", any case). Sets `faults`'
// nakFor and nakCommand; false for anything else.
[[nodiscard]] bool parseNakScope(const QString &text, SimFaults *faults);

} // namespace tipscope::sim
