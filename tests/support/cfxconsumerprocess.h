// The independent CFX consumer (tests/cfx/cfx_consumer.py, Python with Debian's
// python3-qpid-proton) as a child process, shared by the CFX tests (tests/cfx/cfxconsumer.h) and
// `tipscope-bench cfx` (tests/bench/cfxtap.h): started on a source address, what it prints taken
// line by line as it comes: "READY" once its link is attached, "BAD: ..." for what did not fit
// CFX (or a transport lost), and one JSON object a message. Debian's /usr/bin/python3 is named
// on purpose: the python3 first on the PATH may not have the binding.
#pragma once

#include <QByteArray>
#include <QProcess>
#include <QStringList>
#include <functional>

namespace tipscope::testing {

class CfxConsumerProcess {
public:
    using LineHandler = std::function<void(const QByteArray &line)>;

    explicit CfxConsumerProcess(LineHandler onLine);
    ~CfxConsumerProcess();
    CfxConsumerProcess(const CfxConsumerProcess &) = delete;
    CfxConsumerProcess &operator=(const CfxConsumerProcess &) = delete;

    // Empty when the consumer can run here, else why not.
    [[nodiscard]] static QString skipReason();
    // Listens on `source` until `count` messages came or `timeoutS` passed; `more`: its other
    // options (a requester's --request, --target, --send-to; --retry-max-s).
    void start(const QString &url, const QString &source, qint64 count, int timeoutS,
               const QStringList &more = {});
    // Hands what it printed since the last call to the handler, a line at a time.
    void read();
    [[nodiscard]] bool isReady() const { return m_ready; }
    [[nodiscard]] QProcess &process() { return m_process; }

private:
    LineHandler m_onLine;
    QProcess m_process;
    QByteArray m_pending;
    bool m_ready = false;
};

} // namespace tipscope::testing
