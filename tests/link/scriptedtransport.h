// ScriptedTransport: a Transport whose other end is the test, for deterministic queue tests.
//
// Every write is recorded (tests assert how many times a frame went out, which proves the retry
// policy). A write is confirmed with bytesWritten() asynchronously: at once (next event loop
// turn), after a delay, or never (to exercise the queue's write watchdog). The test answers with
// arbitrary bytes through answer(), or installs a Responder that is handed each written frame,
// decoded, once its write is confirmed, and returns the bytes to send back (empty: silence).
// Answers are always delivered from the event loop, never inside write(), as a real port does.
#pragma once

#include "link/transport.h"
#include "protocol/frame.h"

#include <QList>
#include <functional>
#include <optional>

namespace tipscope::test {

class ScriptedTransport : public link::Transport {
    Q_OBJECT
public:
    // `attempt` counts the writes of these exact bytes so far, 1 for the first one.
    using Responder = std::function<QByteArray(const protocol::Frame &request, int attempt)>;

    explicit ScriptedTransport(QObject *parent = nullptr);

    void open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    [[nodiscard]] bool isOpen() const override { return m_open; }
    [[nodiscard]] QString description() const override;
    [[nodiscard]] int baudRate() const override { return m_baud; }

    void setBaudRate(int baud) { m_baud = baud; }
    // Delay before bytesWritten(); a negative delay means the write is never confirmed.
    void setConfirmDelayMs(int ms) { m_confirmDelayMs = ms; }
    void setResponder(Responder responder) { m_responder = std::move(responder); }

    // Delivers `bytes` as received data from the event loop, after `delayMs`.
    void answer(const QByteArray &bytes, int delayMs = 0);

    [[nodiscard]] const QList<QByteArray> &writes() const { return m_writes; }
    [[nodiscard]] int writeCount(const QByteArray &bytes) const;
    // The commands of the written frames, in order ("ST1", "ST2", ...).
    [[nodiscard]] QList<QByteArray> writtenCommands() const;

Q_SIGNALS:
    void written(const QByteArray &bytes);

private:
    void confirm(const QByteArray &bytes);

    QList<QByteArray> m_writes;
    Responder m_responder;
    int m_confirmDelayMs = 0;
    int m_baud = 19200;
    bool m_open = false;
};

// The device's side of an exchange, for responders and hand-made answers.
[[nodiscard]] protocol::Frame answerTo(const protocol::Frame &request, const QByteArray &data = {});
[[nodiscard]] protocol::Frame nakTo(const protocol::Frame &request, int code);
// `frame` encoded with its BCC spoiled.
[[nodiscard]] QByteArray withBadBcc(const protocol::Frame &frame);

} // namespace tipscope::test
