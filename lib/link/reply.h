// Reply: the outcome of one request on the line, delivered asynchronously.
//
// A Reply is created by RequestQueue and parented to the owner given there (usually the model
// that asked). Deleting it, or its owner, before the request is sent withdraws the request: the
// queue skips requests that nobody waits for. finished() is emitted exactly once.
#pragma once

#include "protocol/frame.h"

#include <QObject>

namespace tipscope::link {

enum class ReplyError {
    None,
    Timeout,      // no valid answer within the budget, after the retries
    Corrupted,    // answers arrived but failed the BCC or format check, after the retries
    Nak,          // the device refused; nakCode() says why
    Disconnected, // the line went away while the request was pending
    Cancelled,    // the queue was stopped or cleared
    NotOpen,      // the line was not open when the request was made
};

[[nodiscard]] QString replyErrorName(ReplyError e);

class Reply : public QObject {
    Q_OBJECT
public:
    explicit Reply(const protocol::Frame &request, QObject *parent = nullptr);
    ~Reply() override;

    [[nodiscard]] bool isFinished() const { return m_finished; }
    [[nodiscard]] ReplyError error() const { return m_error; }
    [[nodiscard]] bool ok() const { return m_finished && m_error == ReplyError::None; }
    [[nodiscard]] QString errorString() const { return m_errorString; }
    [[nodiscard]] const protocol::Frame &request() const { return m_request; }
    [[nodiscard]] const protocol::Frame &answer() const { return m_answer; }
    [[nodiscard]] int nakCode() const { return m_nakCode; }
    [[nodiscard]] int attempts() const { return m_attempts; }
    [[nodiscard]] qint64 latencyUs() const { return m_latencyUs; }
    // How long before finished() the device took the value it answered with (0 without an
    // answer): a reading is stamped at the instant it describes, not when it was decoded.
    [[nodiscard]] qint64 answerAgeUs() const { return m_answerAgeUs; }
    // The reply deletes itself once finished() has been delivered: what deleteLater() in a slot
    // does, without posting an event (a wake-up of the event loop) for every request of a poll.
    void setDeleteWhenFinished(bool on) { m_deleteWhenFinished = on; }

Q_SIGNALS:
    void finished();

private:
    friend class RequestQueue;
    void finish(ReplyError error, const QString &why);

    protocol::Frame m_request;
    protocol::Frame m_answer;
    bool m_finished = false;
    ReplyError m_error = ReplyError::None;
    QString m_errorString;
    int m_nakCode = 0;
    int m_attempts = 0;
    qint64 m_latencyUs = 0;
    qint64 m_answerAgeUs = 0;
    bool m_deleteWhenFinished = false;
    bool *m_deletedDuringFinish = nullptr; // set while finished() is being delivered
};

} // namespace tipscope::link
