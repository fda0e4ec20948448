// ProcessRun: how a program a test started ended, and what it printed. finishProcess() waits for
// a started QProcess (killing it after `timeoutMs`, which reads as "timed out" on standard error
// and exit code -1; a crash is -2) and collects its output.
#pragma once

#include <QProcess>
#include <QString>

namespace tipscope::testing {

struct ProcessRun {
    int exitCode = -1;
    QString out;
    QString err;
};

inline ProcessRun finishProcess(QProcess &p, int timeoutMs) {
    ProcessRun r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("timed out");
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

} // namespace tipscope::testing
