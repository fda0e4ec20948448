// ConsoleSender: the raw console's one way onto the line, and its monitor-only gate.
//
// What a person composed or typed in the console is sent once and verbatim (Request::raw), with
// no retries, since a retry would put frames on the wire that nobody asked for, through the
// line's RequestQueue, so its answer shows in the console like any other traffic. While
// monitor-only is on, whatever is or may be a write is refused: a W frame, and typed bytes that
// are not one valid R frame. refusal() says beforehand why the gate would refuse something, for
// the widget to show where the person looks; send() reports every outcome through outcome(): a
// refusal or "waiting for the answer" at once, later the answer, the NAK's meaning or the
// failure. The sender does not own the queue; the line it belongs to may go away at any time.
#pragma once

#include "protocol/frame.h"

#include <QObject>
#include <QPointer>

namespace tipscope::link {
class RequestQueue;
}

namespace tipscope::model {

class ConsoleSender : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    // The queue of the line to send on; null: not connected.
    void attach(link::RequestQueue *queue);
    [[nodiscard]] bool isAttached() const { return !m_queue.isNull(); }
    // The robot's address on the attached line, the source of addressed frames (0 when none).
    [[nodiscard]] int robotAddress() const;
    void setMonitorOnly(bool on);
    [[nodiscard]] bool isMonitorOnly() const { return m_monitorOnly; }

    // Why monitor-only refuses this now; empty when the gate lets it through.
    [[nodiscard]] QString refusal(const protocol::Frame &frame) const;
    [[nodiscard]] QString refusal(const QByteArray &bytes) const;
    // Sends a composed frame, or typed bytes; false when refused (outcome() said why).
    bool send(const protocol::Frame &frame);
    bool send(const QByteArray &bytes);
    // Bytes that are not one valid R frame could be anything, a write included.
    [[nodiscard]] static bool mayWrite(const QByteArray &bytes);

Q_SIGNALS:
    // The outcome of the last send, as one line; `failed` for a refusal or a failure.
    void outcome(const QString &text, bool failed);
    // The line or monitor-only changed, so what refusal() and robotAddress() say may have too.
    void gateChanged();

private:
    bool send(const QByteArray &bytes, const QString &what, bool write);

    QPointer<link::RequestQueue> m_queue;
    bool m_monitorOnly = false;
};

} // namespace tipscope::model
