// The commands of tipscope-cli. Each returns the process exit code (see ExitCode) and prints
// results on standard output, problems on standard error.
#pragma once

#include "clisession.h"

#include "model/session.h"
#include "model/workspace/workspacefile.h"

namespace tipscope::journal {
class JournalReader;
}

namespace tipscope::cli {

// The command of s.options() that talks to the devices on the open line (detect, read, write,
// send, monitor, dump, profile).
int runOnLine(CliSession &s);
int runDetect(CliSession &s);
int runRead(CliSession &s);
int runWrite(CliSession &s);
int runSend(CliSession &s);
int runDump(CliSession &s);
int runProfile(CliSession &s);
int runCommands(const CliOptions &o, QTextStream &out, QTextStream &err);
// The line the options name (connection, addressing, the demo's activity), for commands that run
// a Session of their own instead of the CliSession's line.
[[nodiscard]] model::Session::Settings sessionSettingsOf(const CliOptions &o);
// The same as a workspace line, named as docs/mqtt.md says: "demo" for the demo, the serial
// device's name, or the TCP server's host and port.
[[nodiscard]] model::WorkspaceLine workspaceLineOf(const CliOptions &o);
// monitor: the line (or a workspace's lines) through the line service, printed and written.
int runMonitor(const CliOptions &o, QTextStream &out, QTextStream &err);
// monitor --mqtt and/or --cfx: the lines (one, or a workspace's) published as the agent does.
int runMonitorPlant(const CliOptions &o, QTextStream &out, QTextStream &err);
// Their own session (record) or none (measure): recordings, as the Charts page writes them.
int runRecord(const CliOptions &o, QTextStream &out, QTextStream &err);
int runMeasure(const CliOptions &o, QTextStream &out, QTextStream &err);
// The journal and the files beside it: no device.
int runJoints(const CliOptions &o, QTextStream &out, QTextStream &err);
// board SERIAL: one board's record, as text, --json, --csv or --pdf FILE.
int runBoard(const CliOptions &o, QTextStream &out, QTextStream &err);
int runContext(const CliOptions &o, QTextStream &out, QTextStream &err);
int runLimits(const CliOptions &o, QTextStream &out, QTextStream &err);
int runJournal(const CliOptions &o, QTextStream &out, QTextStream &err);
// --journal FILE, or the journal every TipScope program keeps by default.
[[nodiscard]] QString journalPathOf(const CliOptions &o);
// Opens the journal of `o` to report on it (`joints`, `journal show`: read only, unless an older
// schema needs migrating) and runs the one integrity check; kOk, or, after saying why, the exit
// status of the problem's kind.
[[nodiscard]] int openJournalToReport(const CliOptions &o, journal::JournalReader &reader,
                                      QTextStream &err);

// "ST1 350 °C", "HD1 1.60 s", "D12 disabled", "CT1 2 T245", "SMN DME-2C".
[[nodiscard]] QString formatReading(const protocol::ResolvedCommand &cmd, const QByteArray &data,
                                    bool raw);

} // namespace tipscope::cli
