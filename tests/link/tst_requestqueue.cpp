// The request queue keeps its contract (see requestqueue.h) against a scripted peer: one request
// at a time, strict matching, priorities, coalescing, withdrawal, the retry policy proven by send
// counts, and failure reporting. Time budgets are kept small; only counts, order and outcomes are
// asserted, never how long something took at most.
#include "scriptedtransport.h"
#include "testmain.h"

#include "link/requestqueue.h"
#include "protocol/catalog.h"
#include "protocol/framedecoder.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

namespace tst_requestqueue {

using namespace tipscope::link;
using namespace tipscope::protocol;
using tipscope::test::answerTo;
using tipscope::test::nakTo;
using tipscope::test::ScriptedTransport;
using tipscope::test::withBadBcc;

namespace {

constexpr int kNoAnswerWaitMs = 10000; // a generous ceiling for "eventually", never asserted on

QueueSettings quickSettings(int retries = 2, int turnaroundMs = 20) {
    QueueSettings s;
    s.robotAddress = 0;
    s.turnaroundMs = turnaroundMs;
    s.retries = retries;
    s.interFrameGapMs = 0;
    s.lateAnswerWindowMs = 10; // the answer budget rules: retries are not held up in these tests
    return s;
}

// A late answer's window far longer than any test: only the late answer itself ends a hold.
QueueSettings holdUntilTheLateAnswer(int retries) {
    QueueSettings s = quickSettings(retries);
    s.lateAnswerWindowMs = 60000;
    return s;
}

// Plain priority order, with the fairness rule out of the way.
QueueSettings strictPriority() {
    QueueSettings s = quickSettings();
    s.urgentBurst = 1000;
    return s;
}

// Answers every request as a healthy device would: reads with a value, writes without data.
QByteArray answerEverything(const Frame &request, int /*attempt*/) {
    return answerTo(request, request.header == Header::Read ? QByteArray("00350") : QByteArray())
        .encode();
}

Frame makeFrame(Header header, const QByteArray &command, std::optional<int> source,
                std::optional<int> target, const QByteArray &data = {}) {
    Frame f;
    f.header = header;
    f.command = command;
    f.source = source;
    f.target = target;
    f.data = data;
    return f;
}

std::optional<int> targetFromInt(int t) {
    return t < 0 ? std::nullopt : std::optional<int>(t);
}

// A queue on an open scripted line. Members are destroyed owner first, so no reply outlives it.
struct Bench {
    explicit Bench(const QueueSettings &settings = quickSettings()) {
        queue.setSettings(settings);
        queue.setTransport(&transport);
        queue.lineOpened();
    }

    Reply *read(const QByteArray &command, Priority priority = Priority::UserRead,
                std::optional<int> target = 1) {
        return queue.enqueue(Request::read(target, command, priority), &owner);
    }
    Reply *send(const Request &request) { return queue.enqueue(request, &owner); }

    ScriptedTransport transport;
    RequestQueue queue;
    QObject owner;
};

bool allFinished(const QList<Reply *> &replies) {
    for (const Reply *r : replies)
        if (!r->isFinished())
            return false;
    return true;
}

} // namespace

class TestRequestQueue : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void oneRequestIsOutstandingAtATime();
    void answerIsMatchedByHeaderCommandAndSwappedAddresses_data();
    void answerIsMatchedByHeaderCommandAndSwappedAddresses();
    void lateAnswerAfterATimeoutIsStrayAndNeverAnswersTheNextRequest();
    void requestsAreSentByPriority_data();
    void requestsAreSentByPriority();
    void writesKeepTheirOrderAmongThemselves();
    void waitingPollsGetATurnAfterABurstOfUserRequests_data();
    void waitingPollsGetATurnAfterABurstOfUserRequests();
    void identicalPendingReadsAreSentOnce();
    void pendingRequestsCoalesceOnlyWhenIdenticalReads_data();
    void pendingRequestsCoalesceOnlyWhenIdenticalReads();
    void coalescedReadWaitsAtTheMostUrgentPriority();
    void withdrawnRequestIsNeverWritten_data();
    void withdrawnRequestIsNeverWritten();
    void timeoutRetriesReadsExactlyRetriesTimes_data();
    void timeoutRetriesReadsExactlyRetriesTimes();
    void writesAreRetriedOnlyWhenRepeatable_data();
    void writesAreRetriedOnlyWhenRepeatable();
    void nakIsFinalWithItsCodeAndMeaning_data();
    void nakIsFinalWithItsCodeAndMeaning();
    void nak1MeansGarbledAndIsRetried_data();
    void nak1MeansGarbledAndIsRetried();
    void corruptedAnswerIsRetriedBeforeTheTimeout_data();
    void corruptedAnswerIsRetriedBeforeTheTimeout();
    void unreadableDataFieldIsCorruptedAndRetried_data();
    void unreadableDataFieldIsCorruptedAndRetried();
    void answerBudgetStartsWhenTheRequestIsWritten();
    void answerLaterThanTheBudgetIsStray();
    void anAnswerSaysHowOldItsValueIs();
    void garbageInsteadOfAnAnswerIsCountedInTheReason();
    void afterATimeoutTheSameCommandWaitsForTheLateAnswer();
    void aRetryTakesTheLateAnswerOfTheAttemptBeforeAndHoldsTheNextRequest();
    void aHeldWriteKeepsTheWritesBehindItWaiting();
    void aHoldEndsWhenTheWindowPassesWithoutALateAnswer();
    void aSuspectedLateAnswerHoldsTheNextRequestOfItsCommand();
    void unconfirmedWriteFailsOnTheWriteWatchdog();
    void lostLineFailsEveryPendingRequestWithTheReason();
    void requestOnAClosedLineFailsWithNotOpenAsynchronously_data();
    void requestOnAClosedLineFailsWithNotOpenAsynchronously();
    void tapShowsTxRxAndDecodedFrames();
    void timeoutStreakReportsTheRunLength();
    void timeoutStreakCountsRequestsNotRetries();
    void aFrameAfterATimeoutEndsTheTimeoutStreak_data();
    void aFrameAfterATimeoutEndsTheTimeoutStreak();
    void probeSilenceDoesNotLengthenTheTimeoutStreak();
    void corruptedAnswerEndsTheTimeoutStreak();
    void partOfALateAnswerEndsTheTimeoutStreak();
    void aReplyThatDeletesItselfIsGoneAfterItsFinishedEvenWhenItsOwnerWentFirst();
};

void TestRequestQueue::oneRequestIsOutstandingAtATime() {
    Bench b;
    b.transport.setResponder(answerEverything);
    int finished = 0;
    QList<int> finishedWhenWritten;
    connect(&b.transport, &ScriptedTransport::written, this,
            [&] { finishedWhenWritten.append(finished); });

    QList<Reply *> replies;
    for (const char *cmd : {"ST1", "ST2", "ST3"}) {
        replies.append(b.read(cmd));
        connect(replies.back(), &Reply::finished, this, [&] { ++finished; });
    }
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(replies), kNoAnswerWaitMs);

    // Each frame left only after the previous request had its answer.
    QCOMPARE(finishedWhenWritten, QList<int>({0, 1, 2}));
    for (const Reply *r : replies)
        QVERIFY2(r->ok(), qPrintable(r->errorString()));
}

void TestRequestQueue::answerIsMatchedByHeaderCommandAndSwappedAddresses_data() {
    QTest::addColumn<int>("target"); // -1: the request has no addresses
    QTest::addColumn<QByteArray>("answer");
    QTest::addColumn<bool>("matched");

    const QByteArray c("ST1");
    QTest::newRow("A from 01 to 00")
        << 1 << makeFrame(Header::Answer, c, 1, 0, "00350").encode() << true;
    QTest::newRow("N from 01 to 00")
        << 1 << makeFrame(Header::Nak, c, 1, 0, "00004").encode() << true;
    QTest::newRow("other command")
        << 1 << makeFrame(Header::Answer, "ST2", 1, 0, "00350").encode() << false;
    QTest::newRow("other device") << 1 << makeFrame(Header::Answer, c, 2, 0, "00350").encode()
                                  << false;
    QTest::newRow("other robot") << 1 << makeFrame(Header::Answer, c, 1, 5, "00350").encode()
                                 << false;
    QTest::newRow("addresses not swapped")
        << 1 << makeFrame(Header::Answer, c, 0, 1, "00350").encode() << false;
    QTest::newRow("no addresses")
        << 1 << makeFrame(Header::Answer, c, std::nullopt, std::nullopt, "00350").encode() << false;
    QTest::newRow("echo of the request") << 1 << makeFrame(Header::Read, c, 0, 1).encode() << false;
    QTest::newRow("W header") << 1 << makeFrame(Header::Write, c, 1, 0, "00350").encode() << false;
    QTest::newRow("unaddressed A")
        << -1 << makeFrame(Header::Answer, c, std::nullopt, std::nullopt, "00350").encode() << true;
    QTest::newRow("unaddressed request, addressed A")
        << -1 << makeFrame(Header::Answer, c, 1, 0, "00350").encode() << false;
}

void TestRequestQueue::answerIsMatchedByHeaderCommandAndSwappedAddresses() {
    QFETCH(int, target);
    QFETCH(QByteArray, answer);
    QFETCH(bool, matched);

    Bench b(quickSettings(0));
    QSignalSpy written(&b.transport, &ScriptedTransport::written);
    QVERIFY(written.isValid());
    Reply *reply = b.read("ST1", Priority::UserRead, targetFromInt(target));
    QCOMPARE(written.count(), 1);
    b.transport.answer(answer);
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);

    if (matched) {
        QVERIFY(reply->error() == ReplyError::None || reply->error() == ReplyError::Nak);
        QCOMPARE(reply->answer().encode(), answer);
        QCOMPARE(b.queue.stats().stray, 0);
    } else {
        QCOMPARE(reply->error(), ReplyError::Timeout);
        QVERIFY(reply->answer().command.isEmpty());
        QCOMPARE(b.queue.stats().stray, 1);
    }
}

void TestRequestQueue::lateAnswerAfterATimeoutIsStrayAndNeverAnswersTheNextRequest() {
    Bench b(quickSettings(0));
    Reply *first = b.read("ST1");
    const Frame lateAnswer = answerTo(first->request(), "00350");
    QTRY_VERIFY_WITH_TIMEOUT(first->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(first->error(), ReplyError::Timeout);

    // Late while nothing is outstanding.
    b.transport.answer(lateAnswer.encode());
    QTRY_COMPARE_WITH_TIMEOUT(b.queue.stats().stray, 1, kNoAnswerWaitMs);
    QVERIFY(!first->ok());

    // Late while the next request waits: that request still gets its own answer.
    b.transport.setResponder([&](const Frame &request, int) {
        b.transport.answer(lateAnswer.encode());
        return answerTo(request, "00400").encode();
    });
    Reply *second = b.read("ST2");
    QTRY_VERIFY_WITH_TIMEOUT(second->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(second->ok(), qPrintable(second->errorString()));
    QCOMPARE(second->answer().command, QByteArray("ST2"));
    QCOMPARE(second->answer().data, QByteArray("00400"));
    QCOMPARE(b.queue.stats().stray, 2);
}

void TestRequestQueue::requestsAreSentByPriority_data() {
    QTest::addColumn<bool>("mostUrgentFirst");
    QTest::newRow("enqueued least urgent first") << false;
    QTest::newRow("enqueued most urgent first") << true;
}

void TestRequestQueue::requestsAreSentByPriority() {
    QFETCH(bool, mostUrgentFirst);

    Bench b(strictPriority());
    QList<Reply *> replies{b.read("SMN")}; // occupies the line while the others queue up
    QList<Request> requests{
        Request::read(1, "TT1", Priority::Background), Request::read(1, "TT2", Priority::LivePoll),
        Request::read(1, "ST1", Priority::UserRead), Request::write(1, "ST2", "00350")};
    if (mostUrgentFirst)
        std::reverse(requests.begin(), requests.end());
    for (const Request &r : requests)
        replies.append(b.send(r));
    b.transport.setResponder(answerEverything);
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(replies), kNoAnswerWaitMs);

    QCOMPARE(b.transport.writtenCommands(), QList<QByteArray>({"SMN", "ST2", "ST1", "TT2", "TT1"}));
}

void TestRequestQueue::writesKeepTheirOrderAmongThemselves() {
    Bench b(strictPriority());
    QList<Reply *> replies{b.read("SMN")};
    Request lowWrite = Request::write(1, "ST3", "00360");
    lowWrite.priority = Priority::Background; // a write is a write, whatever the caller said
    replies << b.send(Request::write(1, "ST1", "00340")) << b.read("TT1", Priority::LivePoll)
            << b.send(Request::write(1, "ST2", "00350", false)) << b.read("TT2", Priority::UserRead)
            << b.send(lowWrite) << b.send(Request::write(1, "ST4", "00370"));
    b.transport.setResponder(answerEverything);
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(replies), kNoAnswerWaitMs);

    QCOMPARE(b.transport.writtenCommands(),
             QList<QByteArray>({"SMN", "ST1", "ST2", "ST3", "ST4", "TT2", "TT1"}));
}

void TestRequestQueue::waitingPollsGetATurnAfterABurstOfUserRequests_data() {
    QTest::addColumn<int>("urgentBurst");
    QTest::addColumn<QByteArrayList>("expected");

    QTest::newRow("burst 1") << 1 << QByteArrayList{"SMN", "ST1", "TT1", "ST2",
                                                    "TT2", "ST3", "ST4", "ST5"};
    QTest::newRow("burst 2") << 2 << QByteArrayList{"SMN", "ST1", "ST2", "TT1",
                                                    "ST3", "ST4", "TT2", "ST5"};
    QTest::newRow("burst 3") << 3 << QByteArrayList{"SMN", "ST1", "ST2", "ST3",
                                                    "TT1", "ST4", "ST5", "TT2"};
}

void TestRequestQueue::waitingPollsGetATurnAfterABurstOfUserRequests() {
    QFETCH(int, urgentBurst);
    QFETCH(QByteArrayList, expected);

    QueueSettings settings = quickSettings();
    settings.urgentBurst = urgentBurst;
    Bench b(settings);
    QList<Reply *> replies{b.read("SMN"), b.read("TT1", Priority::LivePoll),
                           b.read("TT2", Priority::Background)};
    for (const char *cmd : {"ST1", "ST2", "ST3", "ST4", "ST5"})
        replies.append(b.send(Request::write(1, cmd, "00350")));
    b.transport.setResponder(answerEverything);
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(replies), kNoAnswerWaitMs);

    QCOMPARE(b.transport.writtenCommands(), expected);
}

void TestRequestQueue::identicalPendingReadsAreSentOnce() {
    Bench b;
    Reply *blocker = b.read("SMN");
    QList<Reply *> same{b.read("ST1", Priority::Background), b.read("ST1", Priority::LivePoll),
                        b.read("ST1", Priority::UserRead)};
    const QByteArray wire = same.front()->request().encode();
    b.transport.setResponder(answerEverything);
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(same) && blocker->isFinished(), kNoAnswerWaitMs);

    QCOMPARE(b.transport.writeCount(wire), 1);
    QCOMPARE(b.queue.stats().coalesced, 2);
    for (const Reply *r : same) {
        QVERIFY2(r->ok(), qPrintable(r->errorString()));
        QCOMPARE(r->answer(), answerTo(r->request(), "00350"));
    }
}

void TestRequestQueue::pendingRequestsCoalesceOnlyWhenIdenticalReads_data() {
    QTest::addColumn<bool>("isWrite");
    QTest::addColumn<int>("target");
    QTest::addColumn<QByteArray>("command");
    QTest::addColumn<int>("expectedFrames");

    QTest::newRow("same read") << false << 1 << QByteArray("ST1") << 1;
    QTest::newRow("other device") << false << 10 << QByteArray("ST1") << 2;
    QTest::newRow("no addresses") << false << -1 << QByteArray("ST1") << 2;
    QTest::newRow("other command") << false << 1 << QByteArray("ST2") << 2;
    QTest::newRow("write of the same command") << true << 1 << QByteArray("ST1") << 2;
}

void TestRequestQueue::pendingRequestsCoalesceOnlyWhenIdenticalReads() {
    QFETCH(bool, isWrite);
    QFETCH(int, target);
    QFETCH(QByteArray, command);
    QFETCH(int, expectedFrames);

    Bench b;
    QList<Reply *> replies{b.read("SMN"), b.read("ST1")};
    replies.append(isWrite ? b.send(Request::write(targetFromInt(target), command, "00350"))
                           : b.read(command, Priority::UserRead, targetFromInt(target)));
    b.transport.setResponder(answerEverything);
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(replies), kNoAnswerWaitMs);

    QCOMPARE(b.transport.writes().size(), 1 + expectedFrames);
    QCOMPARE(b.queue.stats().coalesced, expectedFrames == 1 ? 1 : 0);
    for (const Reply *r : replies)
        QVERIFY2(r->ok(), qPrintable(r->errorString()));
}

void TestRequestQueue::coalescedReadWaitsAtTheMostUrgentPriority() {
    Bench b;
    QList<Reply *> replies{b.read("SMN"), b.read("TT1", Priority::Background),
                           b.read("TT2", Priority::LivePoll), b.read("TT1", Priority::UserRead)};
    b.transport.setResponder(answerEverything);
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(replies), kNoAnswerWaitMs);

    QCOMPARE(b.transport.writtenCommands(), QList<QByteArray>({"SMN", "TT1", "TT2"}));
}

void TestRequestQueue::withdrawnRequestIsNeverWritten_data() {
    QTest::addColumn<bool>("deleteOwner");
    QTest::newRow("reply deleted") << false;
    QTest::newRow("owner deleted") << true;
}

void TestRequestQueue::withdrawnRequestIsNeverWritten() {
    QFETCH(bool, deleteOwner);

    Bench b;
    Reply *blocker = b.read("SMN");
    auto owner = std::make_unique<QObject>();
    QPointer<Reply> withdrawn = b.queue.enqueue(Request::read(1, "ST1"), owner.get());
    const QByteArray wire = withdrawn->request().encode();
    Reply *after = b.read("ST2");
    if (deleteOwner)
        owner.reset();
    else
        delete withdrawn.data();
    QVERIFY(withdrawn.isNull());
    b.transport.setResponder(answerEverything);
    QTRY_VERIFY_WITH_TIMEOUT(blocker->isFinished() && after->isFinished(), kNoAnswerWaitMs);

    QVERIFY2(after->ok(), qPrintable(after->errorString()));
    QCOMPARE(b.transport.writeCount(wire), 0);
    QCOMPARE(b.transport.writtenCommands(), QList<QByteArray>({"SMN", "ST2"}));
    QCOMPARE(b.queue.stats().skipped, 1);
}

void TestRequestQueue::timeoutRetriesReadsExactlyRetriesTimes_data() {
    QTest::addColumn<int>("settingsRetries");
    QTest::addColumn<int>("requestRetries"); // -1: the settings decide
    QTest::addColumn<int>("expectedWrites");

    QTest::newRow("no retries") << 0 << -1 << 1;
    QTest::newRow("one retry") << 1 << -1 << 2;
    QTest::newRow("two retries") << 2 << -1 << 3;
    QTest::newRow("three retries") << 3 << -1 << 4;
    QTest::newRow("request overrides settings") << 3 << 1 << 2;
}

void TestRequestQueue::timeoutRetriesReadsExactlyRetriesTimes() {
    QFETCH(int, settingsRetries);
    QFETCH(int, requestRetries);
    QFETCH(int, expectedWrites);

    Bench b(quickSettings(settingsRetries));
    Request r = Request::read(1, "ST1");
    if (requestRetries >= 0)
        r.retries = requestRetries;
    Reply *reply = b.send(r);
    QSignalSpy finished(reply, &Reply::finished);
    QVERIFY(finished.isValid());
    QVERIFY(finished.wait(kNoAnswerWaitMs));

    QCOMPARE(reply->error(), ReplyError::Timeout);
    QCOMPARE(b.transport.writeCount(reply->request().encode()), expectedWrites);
    QCOMPARE(reply->attempts(), expectedWrites);
    QCOMPARE(b.queue.stats().timeouts, expectedWrites);
    QCOMPARE(b.queue.stats().retries, expectedWrites - 1);
    QCOMPARE(finished.count(), 1);
}

void TestRequestQueue::writesAreRetriedOnlyWhenRepeatable_data() {
    QTest::addColumn<bool>("repeatable");
    QTest::addColumn<int>("expectedWrites");
    QTest::newRow("repeatable") << true << 3;
    QTest::newRow("not repeatable") << false << 1;
}

void TestRequestQueue::writesAreRetriedOnlyWhenRepeatable() {
    QFETCH(bool, repeatable);
    QFETCH(int, expectedWrites);

    Bench b(quickSettings(2));
    Reply *reply = b.send(Request::write(1, "ST1", "00350", repeatable));
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);

    QCOMPARE(reply->error(), ReplyError::Timeout);
    QCOMPARE(b.transport.writeCount(reply->request().encode()), expectedWrites);
    QCOMPARE(reply->errorString().contains(QLatin1String("may have carried it out")), !repeatable);
}

void TestRequestQueue::nakIsFinalWithItsCodeAndMeaning_data() {
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("meaning");
    QTest::newRow("NAK 00002") << 2 << QStringLiteral("Format error");
    QTest::newRow("NAK 00003") << 3 << QStringLiteral("Out of range");
    QTest::newRow("NAK 00004") << 4 << QStringLiteral("Control error");
    QTest::newRow("NAK 00005") << 5 << QStringLiteral("Robot mode is off");
}

void TestRequestQueue::nakIsFinalWithItsCodeAndMeaning() {
    QFETCH(int, code);
    QFETCH(QString, meaning);

    Bench b(quickSettings(2));
    b.transport.setResponder(
        [code](const Frame &request, int) { return nakTo(request, code).encode(); });
    Reply *reply = b.send(Request::write(1, "ST1", "00999"));
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);

    QCOMPARE(reply->error(), ReplyError::Nak);
    QCOMPARE(reply->nakCode(), code);
    QVERIFY2(reply->errorString().contains(meaning), qPrintable(reply->errorString()));
    QVERIFY(reply->errorString().contains(Catalog::builtin().nakText(code, Wording::Translated)));
    QCOMPARE(b.transport.writes().size(), 1);
    QCOMPARE(b.queue.stats().naks.value(code), 1);
}

void TestRequestQueue::nak1MeansGarbledAndIsRetried_data() {
    QTest::addColumn<int>("garbledAttempts");
    QTest::addColumn<int>("expectedWrites");
    QTest::addColumn<bool>("ok");
    QTest::newRow("garbled once") << 1 << 2 << true;
    QTest::newRow("garbled twice") << 2 << 3 << true;
    QTest::newRow("garbled every time") << 100 << 3 << false;
}

void TestRequestQueue::nak1MeansGarbledAndIsRetried() {
    QFETCH(int, garbledAttempts);
    QFETCH(int, expectedWrites);
    QFETCH(bool, ok);

    Bench b(quickSettings(2));
    b.transport.setResponder([garbledAttempts](const Frame &request, int attempt) {
        return attempt <= garbledAttempts ? nakTo(request, 1).encode()
                                          : answerTo(request, "00350").encode();
    });
    Reply *reply = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);

    QCOMPARE(b.transport.writeCount(reply->request().encode()), expectedWrites);
    QCOMPARE(reply->ok(), ok);
    if (ok) {
        QCOMPARE(reply->answer().data, QByteArray("00350"));
    } else {
        QCOMPARE(reply->error(), ReplyError::Nak);
        QCOMPARE(reply->nakCode(), 1);
    }
    QCOMPARE(b.queue.stats().timeouts, 0);
}

void TestRequestQueue::corruptedAnswerIsRetriedBeforeTheTimeout_data() {
    QTest::addColumn<int>("corruptedAttempts");
    QTest::addColumn<int>("expectedWrites");
    QTest::addColumn<int>("expectedError");
    QTest::newRow("corrupted once") << 1 << 2 << int(ReplyError::None);
    QTest::newRow("corrupted every time") << 100 << 3 << int(ReplyError::Corrupted);
}

void TestRequestQueue::corruptedAnswerIsRetriedBeforeTheTimeout() {
    QFETCH(int, corruptedAttempts);
    QFETCH(int, expectedWrites);
    QFETCH(int, expectedError);

    Bench b(quickSettings(2));
    b.transport.setResponder([corruptedAttempts](const Frame &request, int attempt) {
        const Frame a = answerTo(request, "00350");
        return attempt <= corruptedAttempts ? withBadBcc(a) : a.encode();
    });
    Reply *reply = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);

    QCOMPARE(int(reply->error()), expectedError);
    QCOMPARE(b.transport.writeCount(reply->request().encode()), expectedWrites);
    QCOMPARE(b.queue.stats().corrupted, qMin(corruptedAttempts, expectedWrites));
    // Retried on the corrupted answer itself, not after waiting for the budget to run out.
    QCOMPARE(b.queue.stats().timeouts, 0);
}

void TestRequestQueue::unreadableDataFieldIsCorruptedAndRetried_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<QByteArray>("code");
    QTest::addColumn<QByteArray>("bad");
    QTest::addColumn<QByteArray>("good");
    QTest::addColumn<int>("badAnswers"); // the first attempts that get the bad field
    QTest::addColumn<bool>("ok");
    QTest::newRow("number, then a good answer")
        << QStringLiteral("DME") << QByteArray("ST1") << QByteArray("ABCDE") << QByteArray("00350")
        << 1 << true;
    QTest::newRow("number, every attempt")
        << QStringLiteral("DME") << QByteArray("ST1") << QByteArray("ABCDE") << QByteArray("00350")
        << 3 << false;
    QTest::newRow("empty number") << QStringLiteral("DME") << QByteArray("TT1") << QByteArray()
                                  << QByteArray("00120") << 3 << false;
    QTest::newRow("delay") << QStringLiteral("DME") << QByteArray("HD1") << QByteArray("1.6")
                           << QByteArray("01.60") << 2 << true;
    QTest::newRow("hex counter") << QStringLiteral("ALE") << QByteArray("DL1") << QByteArray("XYZ")
                                 << QByteArray("0000002A") << 3 << false;
}

void TestRequestQueue::unreadableDataFieldIsCorruptedAndRetried() {
    QFETCH(QString, family);
    QFETCH(QByteArray, code);
    QFETCH(QByteArray, bad);
    QFETCH(QByteArray, good);
    QFETCH(int, badAnswers);
    QFETCH(bool, ok);

    const auto cmd = Catalog::builtin().resolve(family, code, Direction::Read);
    QVERIFY(cmd);
    Bench b(quickSettings(2));
    b.transport.setResponder([&](const Frame &request, int attempt) {
        return answerTo(request, attempt <= badAnswers ? bad : good).encode();
    });
    Reply *reply = b.send(Request::read(1, *cmd));
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);

    QCOMPARE(reply->ok(), ok);
    QCOMPARE(b.queue.stats().corrupted, qMin(badAnswers, 3));
    QCOMPARE(b.transport.writeCount(reply->request().encode()), qMin(badAnswers + 1, 3));
    if (ok) {
        QCOMPARE(reply->answer().data, good);
        return;
    }
    QCOMPARE(reply->error(), ReplyError::Corrupted);
    QVERIFY2(reply->errorString().contains(
                 QStringLiteral("unreadable data field '%1'").arg(QString::fromLatin1(bad))),
             qPrintable(reply->errorString()));
    QCOMPARE(b.queue.stats().timeouts, 0);

    // The same field for a read that names no format (a raw frame, identification) is its answer.
    b.transport.setResponder(
        [&](const Frame &request, int) { return answerTo(request, bad).encode(); });
    Reply *plain = b.read("SMN");
    QTRY_VERIFY_WITH_TIMEOUT(plain->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(plain->ok(), qPrintable(plain->errorString()));
    QCOMPARE(plain->answer().data, bad);
}

void TestRequestQueue::answerBudgetStartsWhenTheRequestIsWritten() {
    Bench b(quickSettings(0, 100));
    const QByteArray wire = Frame::read("ST1").addressed(0, 1).encode();
    const int budget = b.queue.answerBudgetMs(int(wire.size()));
    QVERIFY(budget > 0);
    // The driver takes three budgets to report the bytes written; the device answers right then.
    b.transport.setConfirmDelayMs(3 * budget);
    b.transport.setResponder(answerEverything);
    QElapsedTimer clock;
    clock.start();
    Reply *reply = b.read("ST1");
    QCOMPARE(reply->request().encode(), wire);
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);

    QVERIFY(clock.elapsed() > budget); // later than the budget counted from write()
    QVERIFY2(reply->ok(), qPrintable(reply->errorString()));
    QCOMPARE(reply->attempts(), 1);
    QCOMPARE(b.transport.writes().size(), 1);
    QCOMPARE(b.queue.stats().timeouts, 0);
}

void TestRequestQueue::answerLaterThanTheBudgetIsStray() {
    Bench b(quickSettings(0));
    const QByteArray wire = Frame::read("ST1").addressed(0, 1).encode();
    const int budget = b.queue.answerBudgetMs(int(wire.size()));
    // The device answers five budgets after the request was written: too late.
    b.transport.setResponder([&](const Frame &request, int) {
        b.transport.answer(answerTo(request, "00350").encode(), 5 * budget);
        return QByteArray();
    });
    Reply *reply = b.read("ST1");
    QCOMPARE(reply->request().encode(), wire);
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(reply->error(), ReplyError::Timeout);
    QVERIFY2(reply->errorString().contains(QLatin1String("no answer")),
             qPrintable(reply->errorString()));

    QTRY_COMPARE_WITH_TIMEOUT(b.queue.stats().stray, 1, kNoAnswerWaitMs);
    QVERIFY(!reply->ok());
    QCOMPARE(b.transport.writes().size(), 1);
}

// A value is as old as the time since the device took it: after the request's last byte reached
// it and before its answer's first byte left, never when the answer was decoded. A reading
// stamped at its decoding looked younger by the answer's bytes on the wire and every wait since.
void TestRequestQueue::anAnswerSaysHowOldItsValueIs() {
    Bench b(quickSettings(0, 200));
    constexpr int kAnswerAfterMs = 60;
    b.transport.setResponder([&](const Frame &request, int) {
        b.transport.answer(answerTo(request, "00350").encode(), kAnswerAfterMs);
        return QByteArray();
    });
    Reply *reply = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(reply->ok(), qPrintable(reply->errorString()));
    const double byteUs = 10.0 * 1e6 / b.transport.baudRate();
    const qint64 requestUs = qint64(byteUs * double(reply->request().encode().size()));
    const qint64 answerUs = qint64(byteUs * double(reply->answer().encode().size()));
    const QString said = QStringLiteral("age %1 us, latency %2 us, request %3 us, answer %4 us")
                             .arg(reply->answerAgeUs())
                             .arg(reply->latencyUs())
                             .arg(requestUs)
                             .arg(answerUs);
    QVERIFY2(reply->latencyUs() >= kAnswerAfterMs * 1000, qPrintable(said));
    QVERIFY2(reply->answerAgeUs() >= answerUs, qPrintable(said));
    QVERIFY2(reply->answerAgeUs() <= reply->latencyUs() - requestUs, qPrintable(said));

    // A refusal carries no value, so no age.
    b.transport.setResponder([](const Frame &request, int) { return nakTo(request, 4).encode(); });
    Reply *refused = b.read("ST2");
    QTRY_VERIFY_WITH_TIMEOUT(refused->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(refused->error(), ReplyError::Nak);
    QCOMPARE(refused->answerAgeUs(), 0);
}

// 10 MB of junk on the line was reported as "no answer", which hides a wrong baud rate or noise.
void TestRequestQueue::garbageInsteadOfAnAnswerIsCountedInTheReason() {
    Bench b(quickSettings(2));
    b.transport.setResponder([](const Frame &, int) { return QByteArray(100000, 'x'); });
    Reply *reply = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(reply->error(), ReplyError::Timeout);
    // No translator is installed here: the English plural forms come with the programs'.
    const QString why = reply->errorString();
    QVERIFY2(why.startsWith(QStringLiteral("no answer after 3 attempt")) &&
                 why.contains(QStringLiteral("; 300000 byte")) &&
                 why.endsWith(QStringLiteral(" of garbage came instead")),
             qPrintable(why));

    b.transport.setResponder({});
    Reply *silent = b.read("ST2");
    QTRY_VERIFY_WITH_TIMEOUT(silent->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(!silent->errorString().contains(QStringLiteral("garbage")),
             qPrintable(silent->errorString()));
}

// The frames carry no sequence number: a late answer to a read of ST1 would be taken for the
// next read of ST1 (a read-back would report the value from before a write).
void TestRequestQueue::afterATimeoutTheSameCommandWaitsForTheLateAnswer() {
    Bench b(holdUntilTheLateAnswer(0));
    Reply *first = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(first->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(first->error(), ReplyError::Timeout);

    Reply *second = b.read("ST1");
    QCOMPARE(b.transport.writes().size(), 1); // held: the late answer may still come

    b.transport.answer(answerTo(first->request(), "00350").encode());
    QTRY_COMPARE_WITH_TIMEOUT(b.transport.writes().size(), 2, kNoAnswerWaitMs);
    QCOMPARE(b.queue.stats().stray, 1);
    QCOMPARE(b.queue.stats().lateAnswers, 1);
    QVERIFY(!second->isFinished());

    b.transport.answer(answerTo(second->request(), "00400").encode());
    QTRY_VERIFY_WITH_TIMEOUT(second->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(second->ok(), qPrintable(second->errorString()));
    QCOMPARE(second->answer().data, QByteArray("00400"));
}

// A retry asks the same question, and nothing of its command went out in between: the late
// answer of the attempt before answers it. Then the retry's own answer is still to come.
void TestRequestQueue::aRetryTakesTheLateAnswerOfTheAttemptBeforeAndHoldsTheNextRequest() {
    Bench b(holdUntilTheLateAnswer(1));
    Reply *read = b.read("ST1");
    QTRY_COMPARE_WITH_TIMEOUT(b.transport.writes().size(), 2, kNoAnswerWaitMs);
    QCOMPARE(b.queue.stats().timeouts, 1);
    b.transport.answer(answerTo(read->request(), "00350").encode()); // attempt 1's, late
    QTRY_VERIFY_WITH_TIMEOUT(read->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(read->ok(), qPrintable(read->errorString()));
    QCOMPARE(read->answer().data, QByteArray("00350"));

    Reply *next = b.read("ST1");
    b.transport.setResponder([](const Frame &request, int) {
        return request.command == "ST2" ? answerTo(request, "00200").encode() : QByteArray();
    });
    Reply *other = b.read("ST2"); // other commands go meanwhile
    QTRY_VERIFY_WITH_TIMEOUT(other->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(other->ok(), qPrintable(other->errorString()));
    QCOMPARE(b.transport.writtenCommands(), QList<QByteArray>({"ST1", "ST1", "ST2"}));

    b.transport.answer(answerTo(read->request(), "00350").encode()); // attempt 2's own
    QTRY_COMPARE_WITH_TIMEOUT(b.transport.writes().size(), 4, kNoAnswerWaitMs);
    QCOMPARE(b.queue.stats().lateAnswers, 1);
    b.transport.answer(answerTo(next->request(), "00400").encode());
    QTRY_VERIFY_WITH_TIMEOUT(next->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(next->answer().data, QByteArray("00400"));
}

void TestRequestQueue::aHeldWriteKeepsTheWritesBehindItWaiting() {
    Bench b(holdUntilTheLateAnswer(0));
    Reply *first = b.send(Request::write(1, "ST1", "00400"));
    QTRY_VERIFY_WITH_TIMEOUT(first->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(first->error(), ReplyError::Timeout);

    b.transport.setResponder([](const Frame &request, int) {
        return request.command == "ST1" ? QByteArray() : answerEverything(request, 1);
    });
    Reply *again = b.send(Request::write(1, "ST1", "00410"));
    Reply *second = b.send(Request::write(1, "ST2", "00420"));
    Reply *read = b.read("ST3");
    QTRY_VERIFY_WITH_TIMEOUT(read->isFinished(), kNoAnswerWaitMs);
    QVERIFY(read->ok());
    QCOMPARE(b.transport.writtenCommands(), QList<QByteArray>({"ST1", "ST3"}));

    b.transport.setResponder(answerEverything);
    b.transport.answer(answerTo(first->request()).encode()); // the first write's, late
    QTRY_VERIFY_WITH_TIMEOUT(again->isFinished() && second->isFinished(), kNoAnswerWaitMs);
    QVERIFY(again->ok() && second->ok());
    QCOMPARE(b.transport.writtenCommands(), QList<QByteArray>({"ST1", "ST3", "ST1", "ST2"}));
    QCOMPARE(b.transport.writes().at(2), again->request().encode());
}

void TestRequestQueue::aHoldEndsWhenTheWindowPassesWithoutALateAnswer() {
    QueueSettings s = quickSettings(0);
    s.lateAnswerWindowMs = 300;
    Bench b(s);
    Reply *first = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(first->isFinished(), kNoAnswerWaitMs);
    b.transport.setResponder(answerEverything);
    Reply *second = b.read("ST1");
    QCOMPARE(b.transport.writes().size(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(second->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(second->ok(), qPrintable(second->errorString()));
    QCOMPARE(b.transport.writes().size(), 2);
    QCOMPARE(b.queue.stats().lateAnswers, 0);
}

void TestRequestQueue::aSuspectedLateAnswerHoldsTheNextRequestOfItsCommand() {
    Bench b(holdUntilTheLateAnswer(0));
    b.queue.holdForLateAnswer(1, "ST1");
    Reply *held = b.read("ST1");
    Reply *free = b.read("ST2");
    Reply *otherDevice = b.read("ST1", Priority::UserRead, 2);
    QCOMPARE(b.transport.writtenCommands(), QList<QByteArray>({"ST2"}));
    b.transport.answer(answerTo(free->request(), "00200").encode());
    QTRY_VERIFY_WITH_TIMEOUT(free->isFinished(), kNoAnswerWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(b.transport.writes().size(), 2, kNoAnswerWaitMs);
    QCOMPARE(b.transport.writes().last(), otherDevice->request().encode());
    b.transport.answer(answerTo(otherDevice->request(), "00300").encode());
    QTRY_VERIFY_WITH_TIMEOUT(otherDevice->isFinished(), kNoAnswerWaitMs);

    b.transport.answer(answerTo(held->request(), "00350").encode()); // the suspected answer's own
    QTRY_COMPARE_WITH_TIMEOUT(b.transport.writes().size(), 3, kNoAnswerWaitMs);
    b.transport.answer(answerTo(held->request(), "00400").encode());
    QTRY_VERIFY_WITH_TIMEOUT(held->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(held->answer().data, QByteArray("00400"));
}

void TestRequestQueue::unconfirmedWriteFailsOnTheWriteWatchdog() {
    Bench b(quickSettings(0));
    b.transport.setConfirmDelayMs(-1);
    b.transport.setResponder(answerEverything); // never consulted: the bytes never left
    Reply *reply = b.read("ST1");
    QSignalSpy finished(reply, &Reply::finished);
    QVERIFY(finished.isValid());
    QVERIFY(finished.wait(kNoAnswerWaitMs));

    QCOMPARE(reply->error(), ReplyError::Timeout);
    QVERIFY2(reply->errorString().contains(QLatin1String("could not be written")),
             qPrintable(reply->errorString()));
    QCOMPARE(b.transport.writes().size(), 1);
}

void TestRequestQueue::lostLineFailsEveryPendingRequestWithTheReason() {
    Bench b;
    const QList<Reply *> replies{b.read("SMN"), b.send(Request::write(1, "ST1", "00350")),
                                 b.read("TT1", Priority::Background), b.read("TT2")};
    QCOMPARE(b.queue.pendingCount(), 4);
    QList<QSharedPointer<QSignalSpy>> spies;
    for (Reply *r : replies) {
        spies.append(QSharedPointer<QSignalSpy>::create(r, &Reply::finished));
        QVERIFY(spies.back()->isValid());
    }

    b.queue.lineLost(QStringLiteral("the adapter was unplugged"));
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(replies), kNoAnswerWaitMs);

    for (int i = 0; i < replies.size(); ++i) {
        QCOMPARE(replies[i]->error(), ReplyError::Disconnected);
        QVERIFY2(replies[i]->errorString().contains(QLatin1String("the adapter was unplugged")),
                 qPrintable(replies[i]->errorString()));
        QCOMPARE(spies[i]->count(), 1);
    }
    QCOMPARE(b.queue.pendingCount(), 0);
    QCOMPARE(b.transport.writes().size(), 1);
}

void TestRequestQueue::requestOnAClosedLineFailsWithNotOpenAsynchronously_data() {
    QTest::addColumn<bool>("wasOpen");
    QTest::newRow("never opened") << false;
    QTest::newRow("after the line was lost") << true;
}

void TestRequestQueue::requestOnAClosedLineFailsWithNotOpenAsynchronously() {
    QFETCH(bool, wasOpen);

    ScriptedTransport transport;
    RequestQueue queue;
    queue.setSettings(quickSettings());
    queue.setTransport(&transport);
    if (wasOpen) {
        queue.lineOpened();
        queue.lineLost(QStringLiteral("gone"));
    }
    QObject owner;
    Reply *reply = queue.enqueue(Request::read(1, "ST1"), &owner);
    QVERIFY(!reply->isFinished());
    QSignalSpy finished(reply, &Reply::finished); // connected after enqueue() returned
    QVERIFY(finished.isValid());
    QVERIFY(finished.wait(kNoAnswerWaitMs));

    QCOMPARE(finished.count(), 1);
    QCOMPARE(reply->error(), ReplyError::NotOpen);
    QVERIFY(!reply->errorString().isEmpty());
    QVERIFY(transport.writes().isEmpty());
}

void TestRequestQueue::tapShowsTxRxAndDecodedFrames() {
    Bench b(quickSettings(0));
    QList<TapEvent> events;
    connect(&b.queue.tap(), &FrameTap::event, this,
            [&events](const TapEvent &e) { events.append(e); });
    const Frame answer = answerTo(Frame::read("ST1").addressed(0, 1), "00350");
    const Frame stray = answerTo(Frame::read("ST9").addressed(0, 1), "00001");
    b.transport.setResponder([&](const Frame &, int) { return stray.encode() + answer.encode(); });
    Reply *reply = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(reply->isFinished(), kNoAnswerWaitMs);
    QVERIFY2(reply->ok(), qPrintable(reply->errorString()));

    auto has = [&events](auto predicate) {
        return std::any_of(events.cbegin(), events.cend(), predicate);
    };
    QVERIFY(has([&](const TapEvent &e) {
        return e.kind == TapEvent::Kind::Tx && e.bytes == reply->request().encode();
    }));
    QVERIFY(has([&](const TapEvent &e) {
        return e.kind == TapEvent::Kind::Rx && e.bytes == stray.encode() + answer.encode();
    }));
    QVERIFY(has([&](const TapEvent &e) {
        return e.kind == TapEvent::Kind::Decoded && e.decoded.kind == DecodeEvent::Kind::Frame &&
               e.decoded.frame == answer && !e.stray;
    }));
    QVERIFY(has([&](const TapEvent &e) {
        return e.kind == TapEvent::Kind::Decoded && e.decoded.frame == stray && e.stray;
    }));
    for (const TapEvent &e : events)
        QVERIFY(e.wallMs > 0);
}

void TestRequestQueue::timeoutStreakReportsTheRunLength() {
    Bench b(quickSettings(0));
    QSignalSpy streak(&b.queue, &RequestQueue::timeoutStreak);
    QVERIFY(streak.isValid());
    QList<Reply *> unanswered{b.read("ST1"), b.read("ST2"), b.read("ST3")};
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(unanswered), kNoAnswerWaitMs);

    b.transport.setResponder(answerEverything);
    Reply *answered = b.read("ST4");
    QTRY_VERIFY_WITH_TIMEOUT(answered->isFinished(), kNoAnswerWaitMs);
    QVERIFY(answered->ok());

    b.transport.setResponder({});
    Reply *again = b.read("TT1");
    QTRY_VERIFY_WITH_TIMEOUT(again->isFinished(), kNoAnswerWaitMs);

    QList<int> runs;
    for (const QList<QVariant> &args : std::as_const(streak))
        runs.append(args.at(0).toInt());
    QCOMPARE(runs, QList<int>({1, 2, 3, 1})); // an answer ends the run
}

void TestRequestQueue::timeoutStreakCountsRequestsNotRetries() {
    // requestqueue.h: timeoutStreak counts consecutive *requests* that got no answer at all.
    Bench b(quickSettings(2));
    QSignalSpy streak(&b.queue, &RequestQueue::timeoutStreak);
    QVERIFY(streak.isValid());
    QList<Reply *> unanswered{b.read("ST1"), b.read("ST2")};
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(unanswered), kNoAnswerWaitMs);
    QCOMPARE(b.transport.writes().size(), 6);

    int longest = 0;
    for (const QList<QVariant> &args : std::as_const(streak))
        longest = qMax(longest, args.at(0).toInt());
    QCOMPARE(longest, 2); // two requests, whatever their retries
}

// A slow device answers every request after its budget: each answer arrives late, and each
// proves the device is there. An answer so late that its request's hold is over, or one nobody
// asked for, is still a frame on the wire: the cable is there. Either way the line must not be
// closed as if the cable were out.
void TestRequestQueue::aFrameAfterATimeoutEndsTheTimeoutStreak_data() {
    QTest::addColumn<bool>("late"); // the timed-out request's own answer, or a frame of no one's
    QTest::newRow("the late answer") << true;
    QTest::newRow("a frame nothing waits for") << false;
}

void TestRequestQueue::aFrameAfterATimeoutEndsTheTimeoutStreak() {
    QFETCH(bool, late);
    Bench b(late ? holdUntilTheLateAnswer(0) : quickSettings(0));
    QSignalSpy streak(&b.queue, &RequestQueue::timeoutStreak);
    QVERIFY(streak.isValid());
    for (const QByteArray &command : {QByteArray("ST1"), QByteArray("ST2"), QByteArray("ST3")}) {
        Reply *slow = b.read(command);
        QTRY_VERIFY_WITH_TIMEOUT(slow->isFinished(), kNoAnswerWaitMs);
        QCOMPARE(slow->error(), ReplyError::Timeout);
        const qint64 strayBefore = b.queue.stats().stray;
        b.transport.answer(late ? answerTo(slow->request(), "00350").encode()
                                : makeFrame(Header::Answer, "ST9", 1, 0, "00350").encode());
        QTRY_COMPARE_WITH_TIMEOUT(b.queue.stats().stray, strayBefore + 1, kNoAnswerWaitMs);
        if (late)
            QCOMPARE(b.queue.stats().lateAnswers, streak.size());
    }
    QCOMPARE(streak.size(), 3);
    for (const QList<QVariant> &args : std::as_const(streak))
        QCOMPARE(args.at(0).toInt(), 1);
}

void TestRequestQueue::probeSilenceDoesNotLengthenTheTimeoutStreak() {
    Bench b(quickSettings(0));
    QSignalSpy streak(&b.queue, &RequestQueue::timeoutStreak);
    QVERIFY(streak.isValid());
    const auto probe = [](int address) {
        Request r = Request::read(address, "SMN");
        r.probe = true; // silence from an absent address is a normal outcome of discovery
        return r;
    };
    const QList<Reply *> replies{b.read("ST1"), b.send(probe(20)), b.send(probe(30)),
                                 b.read("ST2")};
    QTRY_VERIFY_WITH_TIMEOUT(allFinished(replies), kNoAnswerWaitMs);
    for (const Reply *r : replies)
        QCOMPARE(r->error(), ReplyError::Timeout);

    QVERIFY(!streak.isEmpty());
    int longest = 0;
    for (const QList<QVariant> &args : std::as_const(streak))
        longest = qMax(longest, args.at(0).toInt());
    QCOMPARE(longest, 2);
    QCOMPARE(streak.last().at(0).toInt(), 2);
}

void TestRequestQueue::corruptedAnswerEndsTheTimeoutStreak() {
    // requestqueue.h: the streak counts requests that got no answer *at all*; a garbled answer is
    // still an answer (the cable and the device are there), so it ends the run.
    Bench b(quickSettings(0));
    QSignalSpy streak(&b.queue, &RequestQueue::timeoutStreak);
    QVERIFY(streak.isValid());
    Reply *silent = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(silent->isFinished(), kNoAnswerWaitMs);
    b.transport.setResponder(
        [](const Frame &request, int) { return withBadBcc(answerTo(request, "00350")); });
    Reply *garbled = b.read("ST2");
    QTRY_VERIFY_WITH_TIMEOUT(garbled->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(garbled->error(), ReplyError::Corrupted);
    b.transport.setResponder({});
    Reply *silentAgain = b.read("ST3");
    QTRY_VERIFY_WITH_TIMEOUT(silentAgain->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(silentAgain->error(), ReplyError::Timeout);

    QVERIFY(!streak.isEmpty());
    QCOMPARE(streak.last().at(0).toInt(), 1);
}

// Under load a late answer arrives in two reads and the next request goes out between them: its
// first half is discarded as leftovers and no frame is ever decoded. The bytes still prove the
// device is there.
void TestRequestQueue::partOfALateAnswerEndsTheTimeoutStreak() {
    Bench b(quickSettings(0));
    QSignalSpy streak(&b.queue, &RequestQueue::timeoutStreak);
    QVERIFY(streak.isValid());
    Reply *first = b.read("ST1");
    QTRY_VERIFY_WITH_TIMEOUT(first->isFinished(), kNoAnswerWaitMs);
    const QByteArray late = answerTo(first->request(), "00350").encode();
    const qint64 receivedBefore = b.queue.stats().receivedBytes;
    b.transport.answer(late.left(late.size() / 2));
    QTRY_COMPARE_WITH_TIMEOUT(b.queue.stats().receivedBytes, receivedBefore + late.size() / 2,
                              kNoAnswerWaitMs);
    Reply *second = b.read("ST2");
    QTRY_VERIFY_WITH_TIMEOUT(second->isFinished(), kNoAnswerWaitMs);
    QCOMPARE(second->error(), ReplyError::Timeout);
    QCOMPARE(streak.size(), 2);
    QCOMPARE(streak.last().at(0).toInt(), 1);
}

// A polled reading's reply goes once its finished() is delivered, without a posted event; when a
// slot deletes its owner (and with it the reply) first, it is not deleted a second time (ASan
// and glibc both report a double delete).
void TestRequestQueue::aReplyThatDeletesItselfIsGoneAfterItsFinishedEvenWhenItsOwnerWentFirst() {
    Bench b;
    b.transport.setResponder(answerEverything);
    QPointer<Reply> kept = b.read("ST1");
    kept->setDeleteWhenFinished(true);
    bool delivered = false;
    connect(kept, &Reply::finished, this, [&] { delivered = kept && kept->ok(); });
    QTRY_VERIFY_WITH_TIMEOUT(!kept, kNoAnswerWaitMs);
    QVERIFY(delivered);

    auto *owner = new QObject;
    QPointer<Reply> orphan = b.queue.enqueue(Request::read(1, "ST2", Priority::UserRead), owner);
    orphan->setDeleteWhenFinished(true);
    connect(orphan, &Reply::finished, this, [&owner] {
        delete owner;
        owner = nullptr;
    });
    QTRY_VERIFY_WITH_TIMEOUT(!owner, kNoAnswerWaitMs);
    QVERIFY(!orphan);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestRequestQueue)

} // namespace tst_requestqueue
#include "tst_requestqueue.moc"
