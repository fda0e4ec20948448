// `tipscope-cli --workspace FILE COMMAND`: detect, dump or joints on every line of a workspace at
// once (monitor opens the workspace through the line service, climonitor.cpp).
//
// Each line runs the single-line command in a thread of its own with its own CliSession (line,
// request queue), so a line that is dead, slow or retrying never holds up another; its options are
// the command line's with the workspace's connection and addressing for that line. Everything a
// line's run prints, on standard output and standard error alike, comes out in whole lines prefixed
// with "[NAME] ". joints reads the journal once per line, narrowed to that line's devices. The exit
// code is the worst of the lines'.
#pragma once

#include "clioptions.h"

#include <QTextStream>

namespace tipscope::cli {

int runWorkspace(const CliOptions &options, QTextStream &out, QTextStream &err);

} // namespace tipscope::cli
