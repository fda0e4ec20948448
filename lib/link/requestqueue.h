// RequestQueue: the one queue every request to a serial line goes through.
//
// Contract:
//  - One request is outstanding at a time. Its answer is the first valid A or N frame with the
//    same command and the swapped addresses (or none, in the mode without addresses); any other
//    valid frame is stray: counted, shown on the tap, and dropped, never matched to the wrong
//    request.
//  - The answer budget starts when the transport reports the request's last byte written, and is
//    the wire time of the request and of the longest answer at the line's baud rate (bytesWritten
//    means "handed to the driver", not "on the wire") plus the device turnaround.
//  - An answer to a read that names the catalog's view of its command (Request::format) must
//    carry a data field that decodes for that command's kind; one that does not ("ABCDE" for a
//    temperature) is no valid answer: it is counted as corrupted, like a BCC error.
//  - A timeout, a corrupted answer (BCC or format error, or an unreadable data field) or NAK 00001
//    (the device saw our frame garbled) is retried up to `retries` times for reads and for writes
//    marked repeatable; any other NAK is final and reported with its code and meaning.
//  - Late answers: the frames carry no sequence number, so an answer that comes after its
//    request timed out would be taken for the next request of the same command and device.
//    After a timeout, no other request of that command to that device goes out until the late
//    answer's window has passed (lateAnswerWindowMs, or the answer budget if longer) or every
//    answer still expected arrived in it and was discarded as stray. Other requests go on
//    meanwhile, writes still in their order. The request's own retries are not held: a late
//    answer to an earlier attempt answers the same question, and nothing of that command went
//    out in between. holdForLateAnswer() opens the same window when a caller suspects that an
//    answer it got was a late one (a read-back that differs).
//  - Priorities: writes > user reads > live polling > background. Every write goes into the
//    write class, first in first out, so writes are never reordered among themselves. A read
//    identical to one still waiting in the queue joins it instead of being sent twice.
//  - Fairness: after urgentBurst requests in a row from the two user classes while polls were
//    waiting, one poll goes first, so a long user operation (a profile apply, a dump) cannot
//    freeze the live values; a single user request still never waits behind more than one poll.
//  - A request that got no answer but bytes outside any frame says how many in its reason.
//  - Deleting a Reply (or the owner it was parented to) before its request is sent withdraws
//    the request. A lost line fails every pending request with the reason; nothing is dropped
//    silently. Requests made while the line is closed fail at once with NotOpen.
#pragma once

#include "frametap.h"
#include "lateanswers.h"
#include "linkstats.h"
#include "reply.h"

#include "protocol/catalog.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>
#include <array>
#include <deque>
#include <optional>

namespace tipscope::link {

class Transport;

enum class Priority { UserWrite = 0, UserRead = 1, LivePoll = 2, Background = 3 };

struct Request {
    protocol::Header header = protocol::Header::Read;
    QByteArray command;
    QByteArray data;
    std::optional<int> target; // set: addressed frame from the robot address to this device
    Priority priority = Priority::UserRead;
    bool repeatable = true;     // a write that may be sent again when its answer was lost
    QByteArray raw;             // when set, sent verbatim (the console's raw frames)
    std::optional<int> retries; // overrides QueueSettings::retries (discovery probes use fewer)
    // The device turnaround is at least this (QueueSettings::turnaroundMs when that is longer):
    // a named device's identification is often the first request on a line just opened, where
    // a late answer fails the whole command while an absent device only costs the wait.
    int minTurnaroundMs = 0;
    bool probe = false; // silence is a normal answer (discovery): not counted towards a lost line
    // The catalog's view of a read's command: an answer whose data field does not decode for it
    // is corrupted. Unset (raw frames, identification before the family is known): any data.
    std::optional<protocol::ResolvedCommand> format;

    [[nodiscard]] static Request read(std::optional<int> target, const QByteArray &command,
                                      Priority priority = Priority::UserRead);
    [[nodiscard]] static Request read(std::optional<int> target,
                                      const protocol::ResolvedCommand &command,
                                      Priority priority = Priority::UserRead);
    [[nodiscard]] static Request write(std::optional<int> target, const QByteArray &command,
                                       const QByteArray &data, bool repeatable = true);
};

struct QueueSettings {
    int robotAddress = 0;
    int turnaroundMs = 100;
    int urgentBurst = 3; // user requests in a row before a waiting poll gets one turn
    int retries = 2;
    int interFrameGapMs = 0;
    // After a timeout, how long a late answer is still expected (see the contract above).
    int lateAnswerWindowMs = 500;
};

class RequestQueue : public QObject {
    Q_OBJECT
public:
    explicit RequestQueue(QObject *parent = nullptr);
    ~RequestQueue() override;

    void setTransport(Transport *transport); // not owned
    void setSettings(const QueueSettings &settings) { m_settings = settings; }
    [[nodiscard]] const QueueSettings &settings() const { return m_settings; }

    // The Reply is parented to `owner` (may be null: then the caller deletes it).
    Reply *enqueue(const Request &request, QObject *owner);

    // The answer to the last request of `command` to `target` may have been the late answer of an
    // earlier one: hold the next such request as after a timeout.
    void holdForLateAnswer(std::optional<int> target, const QByteArray &command);

    void lineOpened();
    void lineLost(const QString &reason);
    void stop(const QString &reason);

    [[nodiscard]] int pendingCount() const;
    [[nodiscard]] bool isOpen() const { return m_open; }
    [[nodiscard]] const LinkStats &stats() const { return m_stats; }
    void resetStats() { m_stats = {}; }
    [[nodiscard]] qint64 nowMs() const { return m_clock.elapsed(); }
    [[nodiscard]] FrameTap &tap() { return m_tap; }
    // The answer budget for a frame of `requestBytes`, in ms (exposed for tests and docs).
    [[nodiscard]] int answerBudgetMs(int requestBytes, int minTurnaroundMs = 0) const;

Q_SIGNALS:
    // Consecutive requests that got no answer at all: a hint that the cable is gone. Any byte
    // received ends the run: an answer of any kind, a garbled one, one that came after its
    // request timed out, or part of one.
    void timeoutStreak(int count);
    void statsChanged();

private:
    struct Entry {
        Request request;
        protocol::Frame frame; // what the bytes say, for matching
        bool matchAnything = false;
        QList<QPointer<Reply>> replies;
        int attempts = 0;
        qint64 firstSentUs = 0;
        qint64 lastSentUs = 0;
        qint64 garbageBytes = 0; // bytes outside any frame while it was open, for the reason
        int requestBytes = 0;    // of the last attempt
        qint64 answerAgeUs = 0;  // see answerAgeUs()
        [[nodiscard]] bool wanted() const;
    };
    enum class State { Idle, Writing, Waiting, Gap };

    void sendNext();
    [[nodiscard]] std::optional<Entry> takeSendable(std::deque<Entry> &queue, bool keepOrder);
    [[nodiscard]] bool isHeld(const Entry &e) const;
    void hold(const QByteArray &command, std::optional<int> target, int requestBytes,
              int minTurnaroundMs = 0);
    void holdAfterTimeout(const Entry &e);
    void armHoldTimer();
    void transmit();
    void onBytesWritten(qint64 count);
    void onReceived(const QByteArray &bytes);
    void onTimer();
    void onGapElapsed();
    void startGap();
    void onFrame(const protocol::DecodeEvent &event);
    void onStray(const protocol::DecodeEvent &event);
    void complete(const protocol::Frame &answer, int answerBytes);
    [[nodiscard]] qint64 answerAgeUs(const Entry &e, int answerBytes, qint64 now) const;
    void attemptFailed(ReplyError error, const QString &why);
    void finishCurrent(ReplyError error, const QString &why, const protocol::Frame &answer = {});
    void failEverything(ReplyError error, const QString &why);
    [[nodiscard]] bool canRetry(const Entry &e) const;
    [[nodiscard]] bool matches(const Entry &e, const protocol::Frame &answer) const;
    [[nodiscard]] bool tryCoalesce(const Request &r, Reply *reply);
    static void finishLater(Reply *reply, ReplyError error, const QString &why);
    [[nodiscard]] qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }
    [[nodiscard]] double wireMs(int bytes) const;

    QPointer<Transport> m_transport;
    QueueSettings m_settings;
    std::array<std::deque<Entry>, 4> m_queues;
    std::optional<Entry> m_current;
    State m_state = State::Idle;
    qint64 m_bytesToConfirm = 0;
    bool m_open = false;
    bool m_stopped = false;
    int m_timeoutRun = 0;
    int m_urgentRun = 0;
    QTimer m_timer;
    QTimer m_gapTimer;
    // Within onReceived(), a gap of 0 ms ends when the bytes received are all handled, not at
    // another turn of the event loop: at a full wire that turn was a poll() of every socket per
    // request.
    int m_receiving = 0;
    bool m_gapDue = false;
    QTimer m_holdTimer;
    LateAnswers m_late;
    protocol::FrameDecoder m_decoder;
    QElapsedTimer m_clock;
    LinkStats m_stats;
    FrameTap m_tap;
    QList<QMetaObject::Connection> m_transportConnections;
};

} // namespace tipscope::link
