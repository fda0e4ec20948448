#include "requestqueue.h"

#include "linklogging.h"
#include "transport.h"

#include "protocol/catalog.h"
#include "protocol/datafield.h"
#include "protocol/valuecodec.h"

#include <QtMath>
#include <limits>

namespace tipscope::link {

using namespace tipscope::protocol;

namespace {
constexpr int kLongestAnswerExtra = 16; // a read's answer adds its data field; text may be long
constexpr int kWriteWatchdogMs = 1000;
constexpr int kNakBcc = 1;
} // namespace

Request Request::read(std::optional<int> target, const QByteArray &command, Priority priority) {
    Request r;
    r.header = Header::Read;
    r.command = command;
    r.target = target;
    r.priority = priority;
    return r;
}

Request Request::read(std::optional<int> target, const ResolvedCommand &command,
                      Priority priority) {
    Request r = read(target, command.code, priority);
    r.format = command;
    return r;
}

Request Request::write(std::optional<int> target, const QByteArray &command, const QByteArray &data,
                       bool repeatable) {
    Request r;
    r.header = Header::Write;
    r.command = command;
    r.data = data;
    r.target = target;
    r.priority = Priority::UserWrite;
    r.repeatable = repeatable;
    return r;
}

bool RequestQueue::Entry::wanted() const {
    for (const auto &r : replies)
        if (r && !r->isFinished())
            return true;
    return false;
}

RequestQueue::RequestQueue(QObject *parent)
    : QObject(parent) {
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &RequestQueue::onTimer);
    m_gapTimer.setSingleShot(true);
    m_gapTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_gapTimer, &QTimer::timeout, this, &RequestQueue::onGapElapsed);
    m_holdTimer.setSingleShot(true);
    connect(&m_holdTimer, &QTimer::timeout, this, &RequestQueue::sendNext);
}

RequestQueue::~RequestQueue() {
    stop(tr("the connection was closed"));
}

void RequestQueue::setTransport(Transport *transport) {
    for (const auto &c : m_transportConnections)
        disconnect(c);
    m_transportConnections.clear();
    m_transport = transport;
    if (!transport)
        return;
    m_transportConnections = {
        connect(transport, &Transport::bytesWritten, this, &RequestQueue::onBytesWritten),
        connect(transport, &Transport::received, this, &RequestQueue::onReceived),
    };
}

double RequestQueue::wireMs(int bytes) const {
    const int baud = m_transport ? qMax(1, m_transport->baudRate()) : 19200;
    return bytes * 10.0 * 1000.0 / baud;
}

int RequestQueue::answerBudgetMs(int requestBytes, int minTurnaroundMs) const {
    return int(qCeil(wireMs(requestBytes) + wireMs(requestBytes + kLongestAnswerExtra))) +
           qMax(m_settings.turnaroundMs, minTurnaroundMs);
}

void RequestQueue::finishLater(Reply *reply, ReplyError error, const QString &why) {
    // The caller connects to finished() after enqueue() returns; finishing now would be unseen.
    QTimer::singleShot(0, reply, [reply, error, why] { reply->finish(error, why); });
}

Reply *RequestQueue::enqueue(const Request &request, QObject *owner) {
    Frame frame;
    if (request.raw.isEmpty()) {
        frame.header = request.header;
        frame.command = request.command;
        frame.data = request.data;
        if (request.target) {
            frame.source = m_settings.robotAddress;
            frame.target = *request.target;
        }
    } else if (auto parsed = parseFrame(request.raw)) {
        frame = *parsed;
    }
    auto *reply = new Reply(frame, owner);
    if (m_stopped) {
        finishLater(reply, ReplyError::Cancelled, tr("the connection is closing"));
        return reply;
    }
    if (!m_open) {
        finishLater(reply, ReplyError::NotOpen, tr("not sent: the line is not connected"));
        return reply;
    }
    if (tryCoalesce(request, reply))
        return reply;
    Entry e;
    e.request = request;
    if (request.header == Header::Write && request.raw.isEmpty())
        e.request.priority = Priority::UserWrite;
    e.frame = frame;
    e.matchAnything = !request.raw.isEmpty() && !parseFrame(request.raw);
    e.replies.append(reply);
    m_queues[size_t(e.request.priority)].push_back(std::move(e));
    if (m_state == State::Idle)
        sendNext();
    return reply;
}

void RequestQueue::transmit() {
    Entry &e = *m_current;
    const QByteArray bytes = e.request.raw.isEmpty() ? e.frame.encode() : e.request.raw;
    if (m_decoder.pendingBytes() > 0) {
        // Leftovers of an earlier, broken answer must not glue onto this request's answer.
        m_stats.discardedBytes += m_decoder.pendingBytes();
        m_decoder.reset();
    }
    ++e.attempts;
    if (e.attempts > 1)
        ++m_stats.retries;
    e.lastSentUs = nowUs();
    if (e.attempts == 1)
        e.firstSentUs = e.lastSentUs;
    ++m_stats.sent;
    m_stats.sentBytes += bytes.size();
    m_bytesToConfirm = bytes.size();
    e.requestBytes = int(bytes.size());
    m_state = State::Writing;
    m_timer.start(kWriteWatchdogMs + int(2 * wireMs(int(bytes.size()))));
    m_tap.tx(bytes);
    qCDebug(lcLinkHex).noquote() << "TX" << bytes.toHex(' ');
    m_transport->write(bytes);
}

void RequestQueue::onBytesWritten(qint64 count) {
    if (m_state != State::Writing)
        return;
    m_bytesToConfirm -= count;
    if (m_bytesToConfirm > 0)
        return;
    m_state = State::Waiting;
    // The size transmit() sent: encoding the frame again for it cost an allocation or three.
    m_timer.start(answerBudgetMs(m_current->requestBytes, m_current->request.minTurnaroundMs));
}

bool RequestQueue::matches(const Entry &e, const Frame &a) const {
    if (e.matchAnything)
        return true;
    if (a.header != Header::Answer && a.header != Header::Nak)
        return false;
    if (a.command != e.frame.command)
        return false;
    if (e.frame.isAddressed())
        return a.isAddressed() && a.source == e.frame.target && a.target == e.frame.source;
    return !a.isAddressed();
}

void RequestQueue::onReceived(const QByteArray &bytes) {
    m_stats.receivedBytes += bytes.size();
    // Any byte proves the line carries something, so it ends the timeout streak: an answer, a
    // garbled one, one so late that nothing waits for it any more, or a late answer cut in two by
    // the next request (its first half discarded as leftovers, never a frame). A line that carries
    // bytes must not be closed as if it were unplugged; a wrong baud rate's garbage is said with
    // each request instead.
    if (!bytes.isEmpty())
        m_timeoutRun = 0;
    m_tap.rx(bytes);
    qCDebug(lcLinkHex).noquote() << "RX" << bytes.toHex(' ');
    ++m_receiving;
    for (const DecodeEvent &ev : m_decoder.feed(bytes)) {
        const bool waiting = m_current && (m_state == State::Writing || m_state == State::Waiting);
        switch (ev.kind) {
        case DecodeEvent::Kind::Frame:
            if (waiting && matches(*m_current, ev.frame)) {
                onFrame(ev);
            } else {
                onStray(ev);
            }
            break;
        case DecodeEvent::Kind::Garbage:
            m_stats.discardedBytes += ev.raw.size();
            if (m_current)
                m_current->garbageBytes += ev.raw.size();
            m_tap.decoded(ev, false);
            break;
        default:
            ++m_stats.corrupted;
            m_tap.decoded(ev, false);
            if (waiting)
                attemptFailed(ReplyError::Corrupted,
                              tr("the answer was corrupted (%1)").arg(ev.detail));
            break;
        }
    }
    --m_receiving;
    // The frames after an answer in the same read were judged before the next request went out,
    // as they were when the gap was a timer.
    if (m_receiving == 0 && m_gapDue)
        onGapElapsed();
    Q_EMIT statsChanged();
}

void RequestQueue::onStray(const DecodeEvent &ev) {
    ++m_stats.stray;
    m_tap.decoded(ev, true);
    if (!m_late.absorb(ev.frame, m_settings.robotAddress))
        return;
    ++m_stats.lateAnswers;
    if (m_state == State::Idle)
        sendNext(); // what the late answers held back may go now
}

void RequestQueue::onFrame(const DecodeEvent &ev) {
    m_tap.decoded(ev, false);
    const Request &r = m_current->request;
    const bool checked = r.format && r.header == Header::Read && ev.frame.header == Header::Answer;
    if (!checked || decodeAnswer(*r.format, ev.frame.data)) {
        complete(ev.frame, int(ev.raw.size()));
        return;
    }
    // A well-framed answer whose data field means nothing for the command is as good as a
    // garbled one: taking it would print or store nonsense.
    ++m_stats.corrupted;
    const QString why =
        tr("unreadable data field '%1' in the answer").arg(QString::fromLatin1(ev.frame.data));
    m_tap.note(why);
    attemptFailed(ReplyError::Corrupted, why);
}

void RequestQueue::onTimer() {
    if (!m_current)
        return;
    if (m_state == State::Writing) {
        attemptFailed(ReplyError::Timeout, tr("the request could not be written"));
        return;
    }
    if (m_state == State::Waiting)
        attemptFailed(ReplyError::Timeout, tr("no answer"));
}

void RequestQueue::complete(const Frame &answer, int answerBytes) {
    m_timer.stop();
    Entry &e = *m_current;
    const qint64 now = nowUs();
    const qint64 latency = now - e.lastSentUs;
    e.answerAgeUs = answerAgeUs(e, answerBytes, now);
    m_stats.recordAnswer(latency, now / 1000);
    if (answer.header == Header::Nak) {
        const int code = parseNumber(answer.data).value_or(-1);
        m_stats.naks[code] += 1;
        if (code == kNakBcc && canRetry(e)) {
            m_state = State::Gap;
            startGap();
            return;
        }
        finishCurrent(ReplyError::Nak,
                      tr("NAK %1: %2")
                          .arg(QString::fromLatin1(answer.data),
                               Catalog::builtin().nakText(code, Wording::Translated)),
                      answer);
        return;
    }
    finishCurrent(ReplyError::None, {}, answer);
}

// The device took the value it answers with after the request's last byte reached it and before
// its answer's first byte left: the middle of that window, as far as the wire's own time tells
// it. A value stamped when its answer was decoded is older than its stamp by the answer's bytes
// on the wire (8 ms for a tip reading at 19200 baud) and any wait for the event loop since.
qint64 RequestQueue::answerAgeUs(const Entry &e, int answerBytes, qint64 now) const {
    const qint64 reached = e.lastSentUs + qint64(wireMs(e.requestBytes) * 1000);
    const qint64 answered = qMax(reached, now - qint64(wireMs(answerBytes) * 1000));
    return qBound<qint64>(0, now - (reached + answered) / 2, now - e.lastSentUs);
}

bool RequestQueue::canRetry(const Entry &e) const {
    const bool safe = e.request.header == Header::Read || e.request.repeatable;
    return safe && e.attempts <= e.request.retries.value_or(m_settings.retries) && e.wanted();
}

void RequestQueue::attemptFailed(ReplyError error, const QString &why) {
    m_timer.stop();
    Entry &e = *m_current;
    const bool timeout = error == ReplyError::Timeout;
    if (timeout) {
        holdAfterTimeout(e);
        ++(e.request.probe ? m_stats.probesUnanswered : m_stats.timeouts);
        m_tap.note(tr("%1: %2 (attempt %3)").arg(e.frame.toString(), why).arg(e.attempts));
    }
    const bool retry = canRetry(e);
    qCDebug(lcLink).noquote() << e.frame.toString() << replyErrorName(error) << why << "attempt"
                              << e.attempts << (retry ? "retrying" : "giving up");
    if (retry) {
        m_state = State::Gap;
        startGap();
        return;
    }
    // The streak counts requests that got no answer at all, not attempts; a probe's silence is
    // expected and counts for nothing.
    const bool lengthensStreak = timeout && !e.request.probe;
    if (lengthensStreak)
        ++m_timeoutRun;
    const int run = m_timeoutRun;
    QString text = tr("%1 after %n attempt(s)", nullptr, e.attempts).arg(why);
    if (timeout && e.garbageBytes > 0) // "no answer" alone would hide a wrong baud rate or noise
        text += QStringLiteral("; ") +
                tr("%n byte(s) of garbage came instead", nullptr,
                   int(qMin<qint64>(e.garbageBytes, std::numeric_limits<int>::max())));
    if (e.request.header == Header::Write && !e.request.repeatable)
        text += tr("; the device may have carried it out: check before repeating");
    finishCurrent(error, text);
    if (lengthensStreak)
        Q_EMIT timeoutStreak(run);
}

void RequestQueue::finishCurrent(ReplyError error, const QString &why, const Frame &answer) {
    Entry e = std::move(*m_current);
    m_current.reset();
    m_state = State::Gap;
    startGap();
    const int nak = error == ReplyError::Nak ? parseNumber(answer.data).value_or(-1) : 0;
    for (const QPointer<Reply> &r : e.replies) {
        if (!r)
            continue;
        r->m_answer = answer;
        r->m_attempts = e.attempts;
        r->m_nakCode = nak;
        r->m_latencyUs = nowUs() - e.firstSentUs;
        r->m_answerAgeUs = error == ReplyError::None ? e.answerAgeUs : 0;
        r->finish(error, why);
    }
}

void RequestQueue::startGap() {
    if (m_receiving > 0 && m_settings.interFrameGapMs <= 0)
        m_gapDue = true;
    else
        m_gapTimer.start(m_settings.interFrameGapMs);
}

void RequestQueue::onGapElapsed() {
    m_gapDue = false;
    if (m_current) {
        if (m_open && m_transport)
            transmit();
        return;
    }
    m_state = State::Idle;
    sendNext();
}

void RequestQueue::failEverything(ReplyError error, const QString &why) {
    m_timer.stop();
    m_gapTimer.stop();
    m_gapDue = false;
    m_holdTimer.stop();
    m_state = State::Idle;
    m_decoder.reset();
    m_timeoutRun = 0;
    QList<QPointer<Reply>> replies;
    if (m_current)
        replies += m_current->replies;
    m_current.reset();
    for (auto &q : m_queues) {
        for (const Entry &e : q)
            replies += e.replies;
        q.clear();
    }
    for (const QPointer<Reply> &r : replies)
        if (r)
            r->finish(error, why);
}

void RequestQueue::lineOpened() {
    m_open = true;
    m_decoder.reset();
    sendNext();
}

void RequestQueue::lineLost(const QString &reason) {
    m_open = false;
    m_tap.note(tr("line lost: %1").arg(reason));
    qCDebug(lcLink).noquote() << "line lost:" << reason;
    failEverything(ReplyError::Disconnected, tr("the line was lost: %1").arg(reason));
}

void RequestQueue::stop(const QString &reason) {
    m_stopped = true;
    m_open = false;
    failEverything(ReplyError::Cancelled, reason);
}

} // namespace tipscope::link
