// CliSession: one run of tipscope-cli: the line, the devices on it, and synchronous-looking
// waits built on the asynchronous queue (a local event loop per reply, never a busy wait).
#pragma once

#include "clioptions.h"

#include "link/discovery.h"
#include "model/device/devicemodel.h"
#include "protocol/catalog.h"

#include <QTextStream>
#include <memory>

namespace tipscope::sim {
class SimLine;
}

namespace tipscope::cli {

class CliSession {
    Q_DECLARE_TR_FUNCTIONS(CliSession)
public:
    // Prints on standard output and error, or on `out` and `err` when given (not owned).
    explicit CliSession(const CliOptions &options, QIODevice *out = nullptr,
                        QIODevice *err = nullptr);
    ~CliSession();

    // Opens the line; returns kOk or the exit code after printing why.
    int open();
    // Finds the devices (or uses --addr / --no-addr); returns kOk or an exit code.
    int resolveDevices();
    [[nodiscard]] const QList<link::DeviceInfo> &devices() const { return m_devices; }
    // The device that accepts `code` in `direction`, stations first.
    [[nodiscard]] const link::DeviceInfo *deviceFor(const QByteArray &code,
                                                    protocol::Direction direction) const;
    [[nodiscard]] const link::DeviceInfo *firstStation() const;
    // The model of `device` (a station or the feeder) on this session's line, as the GUI has it.
    [[nodiscard]] std::unique_ptr<model::DeviceModel> model(const link::DeviceInfo &device);

    // Sends and waits; the Reply stays valid until the session ends.
    link::Reply *ask(const link::Request &request);
    [[nodiscard]] static int exitCodeFor(const link::Reply &reply);
    [[nodiscard]] static int exitCodeFor(link::ReplyError error);

    [[nodiscard]] link::Line &line() { return *m_line; }
    [[nodiscard]] const CliOptions &options() const { return m_options; }
    QTextStream &out() { return m_out; }
    QTextStream &err() { return m_err; }

private:
    void waitForLine();
    [[nodiscard]] QString withPortElided(QString message) const;
    int identify(std::optional<int> address);
    static void waitFor(link::Discovery &discovery);

    CliOptions m_options;
    std::unique_ptr<sim::SimLine> m_demo;
    std::unique_ptr<link::Line> m_line;
    QObject m_owner; // parent of every Reply of the session
    QList<link::DeviceInfo> m_devices;
    QTextStream m_out;
    QTextStream m_err;
};

} // namespace tipscope::cli
