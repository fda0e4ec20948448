// Helpers for end-to-end tests of the command-line programs.
//
// runProgram() runs a built program (tipscope-cli, tipscope-sim) to its end and keeps what it
// printed; finishProcess() does the same for a QProcess the test started itself. SimOnSocat serves
// tipscope-sim on one end of a fresh socat PTY pair and hands out the other end, where a client
// connects as to a serial port; starting it again replaces both.
#pragma once

#include "ptyfixtures.h"

#include <memory>

namespace tipscope::testing {

struct ProgramRun {
    int exitCode = -1; // -2: it crashed; -1: it ran longer than allowed and was killed
    QString out;
    QString err;
};

[[nodiscard]] ProgramRun finishProcess(QProcess &process, int timeoutMs = 60000);
[[nodiscard]] ProgramRun runProgram(const QString &name, const QStringList &args,
                                    int timeoutMs = 60000);

class SimOnSocat {
public:
    // Returns the client's end, or empty with `error` set.
    [[nodiscard]] QString start(const QStringList &simArgs, QString *error);
    [[nodiscard]] SimProcess &sim() { return *m_sim; }

private:
    std::unique_ptr<SocatPair> m_pair;
    std::unique_ptr<SimProcess> m_sim;
};

} // namespace tipscope::testing
