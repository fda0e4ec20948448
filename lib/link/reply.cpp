#include "reply.h"

#include <QCoreApplication>

namespace tipscope::link {

QString replyErrorName(ReplyError e) {
    switch (e) {
    case ReplyError::None:
        return Reply::tr("ok");
    case ReplyError::Timeout:
        return Reply::tr("no answer");
    case ReplyError::Corrupted:
        return Reply::tr("corrupted answer");
    case ReplyError::Nak:
        return Reply::tr("refused (NAK)");
    case ReplyError::Disconnected:
        return Reply::tr("disconnected");
    case ReplyError::Cancelled:
        return Reply::tr("cancelled");
    case ReplyError::NotOpen:
        return Reply::tr("not connected");
    }
    return {};
}

Reply::Reply(const protocol::Frame &request, QObject *parent)
    : QObject(parent)
    , m_request(request) {}

Reply::~Reply() {
    if (m_deletedDuringFinish)
        *m_deletedDuringFinish = true;
}

void Reply::finish(ReplyError error, const QString &why) {
    if (m_finished)
        return;
    m_finished = true;
    m_error = error;
    m_errorString = why;
    // A slot may delete the reply, or its owner (and with it the reply): then it is gone already.
    bool deleted = false;
    m_deletedDuringFinish = &deleted;
    Q_EMIT finished();
    if (deleted)
        return;
    m_deletedDuringFinish = nullptr;
    // Nothing touches a reply after finish(): the queue's loops and the deferred finish hold it
    // by QPointer or call finish() last.
    if (m_deleteWhenFinished)
        delete this;
}

} // namespace tipscope::link
