// The independent CFX consumer (cfx_consumer.py, Python with Debian's python3-qpid-proton) run
// from a test: started on a source address, ready once its link is attached, and its output
// read back as the envelopes it received and the "BAD:" lines of what did not fit CFX.
// Debian's /usr/bin/python3 is named on purpose: the python3 first on the PATH may not have
// the binding.
#pragma once

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>
#include <functional>

namespace tipscope::testing {

class CfxConsumer {
public:
    static QString skipReason() {
        QProcess probe;
        probe.start(QStringLiteral("/usr/bin/python3"),
                    {QStringLiteral("-c"), QStringLiteral("import proton")});
        if (!probe.waitForFinished(20000) || probe.exitCode() != 0)
            return QStringLiteral("python3-qpid-proton is not installed for /usr/bin/python3");
        return {};
    }

    ~CfxConsumer() {
        if (m_process.state() != QProcess::NotRunning) {
            m_process.kill();
            m_process.waitForFinished(5000);
        }
    }

    // Listens on `source` for `count` messages; true once the link is attached. `more`: the
    // consumer's other options (a requester's --request, --target, --send-to).
    bool start(const QString &url, const QString &source, int count, const QStringList &more = {}) {
        m_process.setProcessChannelMode(QProcess::MergedChannels);
        m_process.start(QStringLiteral("/usr/bin/python3"),
                        QStringList{QStringLiteral(CFX_CONSUMER), QStringLiteral("--url"), url,
                                    QStringLiteral("--source"), source, QStringLiteral("--count"),
                                    QString::number(count), QStringLiteral("--timeout"),
                                    QStringLiteral("100")} +
                            more);
        return QTest::qWaitFor([this] { return read(), m_ready; }, 30000);
    }

    // Waits (with the event loop) until `count` messages arrived.
    bool waitForMessages(int count, int timeoutMs = 30000) {
        return QTest::qWaitFor([this, count] { return read(), m_messages.size() >= count; },
                               timeoutMs);
    }

    // Waits (with the event loop) until `done` holds for the messages arrived so far.
    bool waitUntil(const std::function<bool(const QList<QJsonObject> &)> &done,
                   int timeoutMs = 30000) {
        return QTest::qWaitFor([this, &done] { return read(), done(m_messages); }, timeoutMs);
    }

    // Waits for the consumer to end on its own (all messages received, or its timeout).
    bool finish() {
        // Waiting with the event loop: the code under test keeps sending meanwhile.
        const bool ended =
            QTest::qWaitFor([this] { return m_process.state() == QProcess::NotRunning; }, 110000);
        read();
        m_output += QStringLiteral("(the consumer %1 with %2)")
                        .arg(ended ? QStringLiteral("ended") : QStringLiteral("did not end"))
                        .arg(m_process.exitCode());
        return ended && m_process.exitStatus() == QProcess::NormalExit && m_process.exitCode() == 0;
    }

    [[nodiscard]] const QList<QJsonObject> &messages() const { return m_messages; }
    [[nodiscard]] const QStringList &complaints() const { return m_bad; }
    // The end of what it printed, for a failure message.
    [[nodiscard]] QString output() const { return m_output.right(1500); }

private:
    void read() {
        m_pending += m_process.readAll();
        qsizetype end;
        while ((end = m_pending.indexOf('\n')) >= 0) {
            const QByteArray line = m_pending.left(end).trimmed();
            m_pending.remove(0, end + 1);
            m_output += QString::fromUtf8(line) + QLatin1Char('\n');
            if (line == "READY")
                m_ready = true;
            else if (line.startsWith("BAD:"))
                m_bad.append(QString::fromUtf8(line));
            else if (line.startsWith('{'))
                m_messages.append(QJsonDocument::fromJson(line).object());
        }
    }

    QProcess m_process;
    QByteArray m_pending;
    QString m_output;
    bool m_ready = false;
    QList<QJsonObject> m_messages;
    QStringList m_bad;
};

} // namespace tipscope::testing
