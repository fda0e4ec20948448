// The independent CFX consumer (support/cfxconsumerprocess.h) run from a test: started on a
// source address, ready once its link is attached, and its output read back as the envelopes it
// received and the "BAD:" lines of what did not fit CFX.
#pragma once

#include "cfxconsumerprocess.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>
#include <functional>

namespace tipscope::testing {

class CfxConsumer {
public:
    static QString skipReason() { return CfxConsumerProcess::skipReason(); }

    // Listens on `source` for `count` messages; true once the link is attached. `more`: the
    // consumer's other options (a requester's --request, --target, --send-to).
    bool start(const QString &url, const QString &source, int count, const QStringList &more = {}) {
        m_consumer.start(url, source, count, 100, more);
        return QTest::qWaitFor([this] { return m_consumer.read(), m_consumer.isReady(); }, 30000);
    }

    // Waits (with the event loop) until `count` messages arrived.
    bool waitForMessages(int count, int timeoutMs = 30000) {
        return QTest::qWaitFor(
            [this, count] { return m_consumer.read(), m_messages.size() >= count; }, timeoutMs);
    }

    // Waits (with the event loop) until `done` holds for the messages arrived so far.
    bool waitUntil(const std::function<bool(const QList<QJsonObject> &)> &done,
                   int timeoutMs = 30000) {
        return QTest::qWaitFor([this, &done] { return m_consumer.read(), done(m_messages); },
                               timeoutMs);
    }

    // Waits for the consumer to end on its own (all messages received, or its timeout).
    bool finish() {
        // Waiting with the event loop: the code under test keeps sending meanwhile.
        QProcess &process = m_consumer.process();
        const bool ended =
            QTest::qWaitFor([&process] { return process.state() == QProcess::NotRunning; }, 110000);
        m_consumer.read();
        m_output += QStringLiteral("(the consumer %1 with %2)")
                        .arg(ended ? QStringLiteral("ended") : QStringLiteral("did not end"))
                        .arg(process.exitCode());
        return ended && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
    }

    [[nodiscard]] const QList<QJsonObject> &messages() const { return m_messages; }
    [[nodiscard]] const QStringList &complaints() const { return m_bad; }
    // The end of what it printed, for a failure message.
    [[nodiscard]] QString output() const { return m_output.right(1500); }

private:
    void take(const QByteArray &line) {
        m_output += QString::fromUtf8(line) + QLatin1Char('\n');
        if (line.startsWith("BAD:"))
            m_bad.append(QString::fromUtf8(line));
        else if (line.startsWith('{'))
            m_messages.append(QJsonDocument::fromJson(line).object());
    }

    QString m_output;
    QList<QJsonObject> m_messages;
    QStringList m_bad;
    CfxConsumerProcess m_consumer{[this](const QByteArray &line) { take(line); }};
};

} // namespace tipscope::testing
