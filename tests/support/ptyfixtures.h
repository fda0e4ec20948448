// Test fixtures for real serial I/O: a socat PTY pair and a tipscope-sim process.
//
// SocatPair starts `socat pty,link=A pty,link=B` in a temporary folder and waits until both
// links exist; whatever is written to one end comes out of the other, as with a null-modem cable.
// SimProcess runs the built tipscope-sim with the given arguments and returns where it serves.
// Both stop their process when destroyed. A test that cannot find socat QSKIPs with the reason.
#pragma once

#include <QByteArray>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <memory>

namespace tipscope::testing {

QString binaryPath(const QString &name);

class SocatPair {
public:
    SocatPair();
    ~SocatPair();
    [[nodiscard]] bool start(QString *error);
    [[nodiscard]] QString deviceEnd() const { return m_dir.path() + QStringLiteral("/device"); }
    [[nodiscard]] QString hostEnd() const { return m_dir.path() + QStringLiteral("/host"); }
    void stop();

private:
    QTemporaryDir m_dir;
    QProcess m_socat;
};

class SimProcess {
public:
    ~SimProcess();
    // Starts tipscope-sim and returns the first line it prints (where it serves), or empty.
    [[nodiscard]] QString start(const QStringList &args, QString *error);
    // Sends one control command and returns its reply line.
    QString command(const QString &line);
    void stop();
    [[nodiscard]] QProcess &process() { return m_process; }

private:
    QProcess m_process;
};

} // namespace tipscope::testing
