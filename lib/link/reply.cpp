#include "reply.h"

namespace tipscope::link {

QString replyErrorName(ReplyError e) {
    switch (e) {
    case ReplyError::None:
        return QStringLiteral("ok");
    case ReplyError::Timeout:
        return QStringLiteral("no answer");
    case ReplyError::Corrupted:
        return QStringLiteral("corrupted answer");
    case ReplyError::Nak:
        return QStringLiteral("refused (NAK)");
    case ReplyError::Disconnected:
        return QStringLiteral("disconnected");
    case ReplyError::Cancelled:
        return QStringLiteral("cancelled");
    case ReplyError::NotOpen:
        return QStringLiteral("not connected");
    }
    return {};
}

Reply::Reply(const protocol::Frame &request, QObject *parent)
    : QObject(parent)
    , m_request(request) {}

void Reply::finish(ReplyError error, const QString &why) {
    if (m_finished)
        return;
    m_finished = true;
    m_error = error;
    m_errorString = why;
    Q_EMIT finished();
}

} // namespace tipscope::link
