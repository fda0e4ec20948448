#include "consolesender.h"

#include "link/requestqueue.h"
#include "protocol/framedecoder.h"

namespace tipscope::model {

using protocol::Frame;
using protocol::Header;

namespace {
QString describeReply(const link::Reply &reply, const QString &what) {
    switch (reply.error()) {
    case link::ReplyError::None:
        return ConsoleSender::tr("%1: answered %2 after %L3 ms")
            .arg(what, reply.answer().toString())
            .arg(double(reply.latencyUs()) / 1000.0, 0, 'f', 1);
    case link::ReplyError::Nak:
        return ConsoleSender::tr("%1: refused, %2").arg(what, reply.errorString());
    case link::ReplyError::Timeout:
        return ConsoleSender::tr("%1: no answer (timeout)").arg(what);
    default:
        return ConsoleSender::tr("%1: %2 (%3)")
            .arg(what, link::replyErrorName(reply.error()), reply.errorString());
    }
}
} // namespace

void ConsoleSender::attach(link::RequestQueue *queue) {
    m_queue = queue;
    Q_EMIT gateChanged();
}

int ConsoleSender::robotAddress() const {
    return m_queue ? m_queue->settings().robotAddress : 0;
}

void ConsoleSender::setMonitorOnly(bool on) {
    if (on == m_monitorOnly)
        return;
    m_monitorOnly = on;
    Q_EMIT gateChanged();
}

bool ConsoleSender::mayWrite(const QByteArray &bytes) {
    const auto frame = protocol::parseFrame(bytes);
    return !frame || frame->header != Header::Read;
}

QString ConsoleSender::refusal(const Frame &frame) const {
    if (m_monitorOnly && frame.header != Header::Read)
        return tr("Monitor-only mode is on: W frames are not sent. Reads still are.");
    return {};
}

QString ConsoleSender::refusal(const QByteArray &bytes) const {
    if (m_monitorOnly && mayWrite(bytes))
        return tr("Monitor-only mode is on: bytes that are not one valid R frame may be a write, "
                  "so they are not sent.");
    return {};
}

bool ConsoleSender::send(const Frame &frame) {
    return send(frame.encode(), frame.toString(), frame.header != Header::Read);
}

bool ConsoleSender::send(const QByteArray &bytes) {
    const auto frame = protocol::parseFrame(bytes);
    const QString what = frame ? frame->toString() : tr("%n raw byte(s)", "", int(bytes.size()));
    return send(bytes, what, mayWrite(bytes));
}

bool ConsoleSender::send(const QByteArray &bytes, const QString &what, bool write) {
    if (!m_queue) {
        Q_EMIT outcome(tr("%1: not sent, not connected").arg(what), true);
        return false;
    }
    if (write && m_monitorOnly) {
        Q_EMIT outcome(tr("%1: not sent, monitor-only mode is on").arg(what), true);
        return false;
    }
    link::Request request;
    request.raw = bytes;
    request.retries = 0;
    request.repeatable = false;
    if (write) {
        request.header = Header::Write;
        request.priority = link::Priority::UserWrite;
    }
    link::Reply *reply = m_queue->enqueue(request, this);
    Q_EMIT outcome(tr("%1: sent, waiting for the answer…").arg(what), false);
    connect(reply, &link::Reply::finished, this, [this, reply, what] {
        reply->deleteLater();
        Q_EMIT outcome(describeReply(*reply, what), !reply->ok());
    });
    return true;
}

} // namespace tipscope::model
