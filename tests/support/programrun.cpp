#include "programrun.h"

namespace tipscope::testing {

ProgramRun runProgram(const QString &name, const QStringList &args, int timeoutMs) {
    QProcess p;
    p.start(binaryPath(name), args);
    return finishProcess(p, timeoutMs);
}

ProgramRun finishProcess(QProcess &p, int timeoutMs) {
    ProgramRun r;
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

QString SimOnSocat::start(const QStringList &simArgs, QString *error) {
    m_sim.reset();
    m_pair = std::make_unique<SocatPair>();
    if (!m_pair->start(error))
        return {};
    m_sim = std::make_unique<SimProcess>();
    if (m_sim->start(simArgs + QStringList{QStringLiteral("--device"), m_pair->deviceEnd()}, error)
            .isEmpty())
        return {};
    return m_pair->hostEnd();
}

} // namespace tipscope::testing
