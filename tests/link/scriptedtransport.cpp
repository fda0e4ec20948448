#include "scriptedtransport.h"

#include "protocol/framedecoder.h"

#include <QTimer>

namespace tipscope::test {

using namespace tipscope::protocol;

ScriptedTransport::ScriptedTransport(QObject *parent)
    : Transport(parent) {}

void ScriptedTransport::open() {
    QTimer::singleShot(0, this, [this] {
        m_open = true;
        Q_EMIT opened();
    });
}

void ScriptedTransport::close() {
    m_open = false;
}

QString ScriptedTransport::description() const {
    return QStringLiteral("scripted");
}

void ScriptedTransport::write(const QByteArray &bytes) {
    m_writes.append(bytes);
    Q_EMIT written(bytes);
    if (m_confirmDelayMs < 0)
        return;
    QTimer::singleShot(m_confirmDelayMs, this, [this, bytes] { confirm(bytes); });
}

void ScriptedTransport::confirm(const QByteArray &bytes) {
    Q_EMIT bytesWritten(bytes.size());
    if (!m_responder)
        return;
    const auto request = parseFrame(bytes);
    if (!request)
        return;
    const QByteArray reply = m_responder(*request, writeCount(bytes));
    if (!reply.isEmpty())
        answer(reply);
}

void ScriptedTransport::answer(const QByteArray &bytes, int delayMs) {
    QTimer::singleShot(delayMs, this, [this, bytes] { Q_EMIT received(bytes); });
}

int ScriptedTransport::writeCount(const QByteArray &bytes) const {
    return int(m_writes.count(bytes));
}

QList<QByteArray> ScriptedTransport::writtenCommands() const {
    QList<QByteArray> out;
    for (const QByteArray &w : m_writes) {
        const auto f = parseFrame(w);
        out.append(f ? f->command : QByteArray("???"));
    }
    return out;
}

Frame answerTo(const Frame &request, const QByteArray &data) {
    Frame a = request;
    a.header = Header::Answer;
    a.data = data;
    a.source = request.target;
    a.target = request.source;
    return a;
}

Frame nakTo(const Frame &request, int code) {
    Frame n = answerTo(request, QByteArray::number(code).rightJustified(5, '0'));
    n.header = Header::Nak;
    return n;
}

QByteArray withBadBcc(const Frame &frame) {
    QByteArray bytes = frame.encode();
    bytes.back() = char(bytes.back() ^ 0x01);
    return bytes;
}

} // namespace tipscope::test
