// A session kept in a journal: the demo station at work through the real session and a real
// SQLite file. Its joints and events are there after the session is gone, stamped with the work
// context another program wrote to the context file, or with its line's own.
#include "journal/journalreader.h"
#include "journal/sessionjournal.h"
#include "journal/workcontextfile.h"
#include "testmain.h"

#include "sim/demoactivity.h"

#include "demosession.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_sessionjournal {

using namespace tipscope;
using namespace tipscope::journal;

namespace {
constexpr int kJointMs =
    sim::DemoActivity::kJointOffsetMs + sim::DemoActivity::kJointEveryMs + 10'000;

struct DemoRun {
    model::DeviceIdentity station;
    model::JointRecord firstJoint;
};

// The demo station at work, kept in `journal` (with its line's own context, when given), until
// its first joint ends; nothing when it does not come in time.
std::optional<DemoRun> keepDemoUntilAJoint(Journal &journal,
                                           std::optional<model::WorkContext> lineContext) {
    model::Session session;
    SessionJournal kept(session, journal, std::move(lineContext));
    QSignalSpy joints(&session.joints(), &model::JointWatcher::jointEnded);
    model::Session::Settings settings = testing::unpacedDemoSettings();
    settings.demoActivity = true;
    session.connectTo(settings);
    if (!QTest::qWaitFor([&] { return session.station() != nullptr; }, 30000) ||
        !QTest::qWaitFor([&] { return !joints.isEmpty(); }, kJointMs))
        return std::nullopt;
    DemoRun run{session.station()->identity(), joints.first().first().value<model::JointRecord>()};
    session.disconnectFromLine();
    return run;
}
} // namespace

class TestSessionJournal : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void jointsAndEventsOfASessionAreKeptWithTheWorkContext();
    void aWorkContextFileThatCannotBeReadIsReportedAndChangesNothing();
    void aLineWithAWorkContextOfItsOwnIsKeptWithIt();
};

void TestSessionJournal::jointsAndEventsOfASessionAreKeptWithTheWorkContext() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    const QString contextPath = dir.filePath(QStringLiteral("context.json"));
    model::DeviceIdentity station;
    model::JointRecord seen;
    const model::WorkContext context{QStringLiteral("WO-7"), QStringLiteral("SN-42"),
                                     QStringLiteral("ana")};
    {
        Journal journal(path);
        WorkContextFollower follower(journal, contextPath);
        QSignalSpy contextChanged(&follower, &WorkContextFollower::contextChanged);
        QVERIFY(contextChanged.isValid());
        // Another program (tipscope-cli context set, a script) writes the file.
        QVERIFY(writeWorkContext(contextPath, context));
        QTRY_COMPARE_WITH_TIMEOUT(journal.context(), context, 10000);

        const auto run = keepDemoUntilAJoint(journal, std::nullopt);
        QVERIFY(run);
        station = run->station;
        seen = run->firstJoint;
        QVERIFY(journal.flush());
    }

    JournalReader reader;
    QVERIFY(reader.open(path));
    const auto stored = reader.joints({});
    QVERIFY2(stored, qPrintable(stored.error()));
    QVERIFY(!stored.value().isEmpty());
    const StoredJoint &last = stored.value().last(); // newest first: the oldest is the first seen
    QCOMPARE(last.record, seen);
    QCOMPARE(last.context, context);
    QVERIFY(!last.uid.isNull());

    EventFilter connections;
    connections.kinds = {JournalEvent::Kind::Connection};
    const auto events = reader.events(connections);
    QVERIFY2(events, qPrintable(events.error()));
    const bool stationConnected =
        std::any_of(events.value().cbegin(), events.value().cend(),
                    [&](const StoredEvent &e) { return e.record.device == station; });
    QVERIFY(stationConnected);
    QCOMPARE(events.value().first().context, context);

    EventFilter changes;
    changes.kinds = {JournalEvent::Kind::ContextChange};
    const auto contextEvents = reader.events(changes);
    QVERIFY2(contextEvents, qPrintable(contextEvents.error()));
    QCOMPARE(contextEvents.value().size(), 1);
}

void TestSessionJournal::aWorkContextFileThatCannotBeReadIsReportedAndChangesNothing() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString contextPath = dir.filePath(QStringLiteral("context.json"));
    Journal journal(dir.filePath(QStringLiteral("journal.sqlite")));
    WorkContextFollower follower(journal, contextPath);
    QSignalSpy unreadable(&follower, &WorkContextFollower::unreadable);
    QVERIFY(unreadable.isValid());
    const model::WorkContext context{QStringLiteral("WO-1"), {}, {}};
    QVERIFY(follower.set(context));
    QCOMPARE(journal.context(), context);

    QFile file(contextPath);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("{\"work_order\": 7");
    file.close();
    QTRY_VERIFY_WITH_TIMEOUT(!unreadable.isEmpty(), 10000);
    QVERIFY2(unreadable.last().first().toString().contains(QStringLiteral("not a JSON object")),
             qPrintable(unreadable.last().first().toString()));
    QCOMPARE(journal.context(), context);
    QVERIFY(journal.flush());
}

// A workspace line with a work context of its own: its joints and events carry it, whatever the
// journal's shared context says; what is not the line's keeps the shared one.
void TestSessionJournal::aLineWithAWorkContextOfItsOwnIsKeptWithIt() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    const model::WorkContext shared{QStringLiteral("WO-shared"), {}, QStringLiteral("ana")};
    const model::WorkContext own{QStringLiteral("WO-line-3"), QStringLiteral("SN-3"),
                                 QStringLiteral("ben")};
    {
        Journal journal(path);
        journal.setContext(shared);
        QVERIFY(keepDemoUntilAJoint(journal, own));
        QCOMPARE(journal.context(), shared);
        QVERIFY(journal.flush());
    }

    JournalReader reader;
    QVERIFY(reader.open(path));
    const auto stored = reader.joints({});
    QVERIFY2(stored, qPrintable(stored.error()));
    QVERIFY(!stored.value().isEmpty());
    for (const StoredJoint &j : stored.value())
        QCOMPARE(j.context, own);
    EventFilter connections;
    connections.kinds = {JournalEvent::Kind::Connection};
    const auto events = reader.events(connections);
    QVERIFY2(events, qPrintable(events.error()));
    QVERIFY(!events.value().isEmpty());
    for (const StoredEvent &e : events.value())
        QCOMPARE(e.context, own);
    EventFilter changes;
    changes.kinds = {JournalEvent::Kind::ContextChange};
    const auto contextEvents = reader.events(changes);
    QVERIFY2(contextEvents, qPrintable(contextEvents.error()));
    QCOMPARE(contextEvents.value().size(), 1); // the journal's own change, with its context
    QCOMPARE(contextEvents.value().first().context, shared);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSessionJournal)

} // namespace tst_sessionjournal
#include "tst_sessionjournal.moc"
