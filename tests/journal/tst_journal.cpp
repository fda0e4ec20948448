// The journal's writer: every field of a joint and an event comes back as appended; `committed`
// names each record by row id and unique id once it is durable; the work context is stamped
// until changed and its change is an event; sent marks take records out of the unsent list;
// closing writes what is queued and later appends are counted lost; a record the database
// refuses is counted lost while the others are kept, and the journal says so in itself.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/journalreader.h"

#include <QDateTime>
#include <QJsonArray>
#include <QMap>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <limits>

namespace tst_journal {

using namespace tipscope;
using namespace tipscope::testing;
using journal::Committed;
using journal::Journal;
using journal::JournalEvent;
using journal::JournalReader;
using journal::JournalState;
using journal::StoredEvent;
using journal::StoredJoint;

namespace {

QList<StoredJoint> allJoints(const QString &path) {
    JournalReader reader;
    if (const auto opened = reader.open(path); !opened)
        qFatal("%s", qPrintable(opened.error()));
    journal::JointFilter filter;
    filter.order = journal::Order::OldestFirst;
    const auto joints = reader.joints(filter);
    return joints ? joints.value() : QList<StoredJoint>();
}

QList<StoredEvent> allEvents(const QString &path) {
    JournalReader reader;
    if (const auto opened = reader.open(path); !opened)
        qFatal("%s", qPrintable(opened.error()));
    journal::EventFilter filter;
    filter.order = journal::Order::OldestFirst;
    const auto events = reader.events(filter);
    return events ? events.value() : QList<StoredEvent>();
}

} // namespace

class TestJournal : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void everyFieldOfAJointSurvivesTheRoundTrip_data();
    void everyFieldOfAJointSurvivesTheRoundTrip();
    void everyFieldOfAnEventSurvivesTheRoundTrip_data();
    void everyFieldOfAnEventSurvivesTheRoundTrip();
    void anEventWithoutATimeIsStampedWithTheWallClock();
    void committedNamesEachDurableRecordByRowAndUniqueId();
    void theContextIsStampedUntilChangedAndItsChangeIsAnEvent();
    void aJointOpenAcrossABoardChangeIsTheEarlierBoards();
    void sentMarksTakeRecordsOutOfTheUnsentListInOrder();
    void closingWritesWhatIsQueuedAndLaterAppendsAreCountedLost();
    void aRecordTheDatabaseRefusesIsCountedLostAndTheOthersAreKept();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    QString m_path;
};

void TestJournal::init() {
    m_dir = std::make_unique<QTemporaryDir>();
    m_path = m_dir->filePath(QStringLiteral("journal.sqlite"));
}

void TestJournal::everyFieldOfAJointSurvivesTheRoundTrip_data() {
    QTest::addColumn<model::JointRecord>("record");
    for (int i = 0; i < 4; ++i) {
        const model::JointRecord j = sampleJoint(i, kT0 + i, 1 + i);
        QTest::addRow("%s", qPrintable(model::jointVerdictName(j.verdict))) << j;
    }
    model::JointRecord unrecovered = sampleJoint(4, kT0, 2);
    QVERIFY(!unrecovered.recoveryMs);
    QTest::newRow("never recovered") << unrecovered;
    model::JointRecord unaddressed = sampleJoint(5, kT0, 3);
    unaddressed.device = {QStringLiteral("10.0.0.7:4001"), std::nullopt, QStringLiteral("DME-1C"),
                          QString()};
    QTest::newRow("device without address or software") << unaddressed;
    model::JointRecord odd = sampleJoint(6, -5, 4);
    odd.tool = QString();
    odd.powerIntegral = 1e-9;
    odd.device.line = QStringLiteral("COM3|x");
    QTest::newRow("no tool, before the epoch, separator in the line") << odd;
}

void TestJournal::everyFieldOfAJointSurvivesTheRoundTrip() {
    QFETCH(model::JointRecord, record);
    const model::WorkContext context{QStringLiteral("WO-9"), QStringLiteral("SN-1"),
                                     QStringLiteral("Jörg")};
    QUuid uid;
    {
        Journal journal(m_path, quickOptions());
        journal.setContext(context);
        uid = journal.append(record);
        QVERIFY(!uid.isNull());
        QVERIFY(journal.flush());
    }
    const QList<StoredJoint> joints = allJoints(m_path);
    QCOMPARE(joints.size(), 1);
    const StoredJoint &stored = joints.first();
    QCOMPARE(stored.uid, uid);
    QVERIFY(stored.id > 0);
    QVERIFY(!stored.sent);
    QVERIFY(stored.context == context);
    QCOMPARE(stored.record.device.key(), record.device.key());
    QCOMPARE(stored.record.port, record.port);
    QCOMPARE(stored.record.tool, record.tool);
    QCOMPARE(stored.record.startMs, record.startMs);
    QCOMPARE(stored.record.endMs, record.endMs);
    QCOMPARE(stored.record.setpoint, record.setpoint);
    QCOMPARE(stored.record.lowestTip, record.lowestTip);
    QCOMPARE(stored.record.dipDepth, record.dipDepth);
    QCOMPARE(stored.record.recoveryMs, record.recoveryMs);
    QCOMPARE(stored.record.durationMs, record.durationMs);
    QCOMPARE(stored.record.powerPeak, record.powerPeak);
    QCOMPARE(stored.record.powerIntegral, record.powerIntegral);
    QCOMPARE(stored.record.verdict, record.verdict);
    QVERIFY(stored.record == record);
}

void TestJournal::everyFieldOfAnEventSurvivesTheRoundTrip_data() {
    QTest::addColumn<JournalEvent>("record");
    QTest::newRow("write with read-back") << sampleEvent(1, kT0, 2);
    JournalEvent profile = sampleEvent(2, kT0 + 5, 1);
    profile.kind = JournalEvent::Kind::ProfileApply;
    profile.severity = JournalEvent::Severity::Warning;
    profile.port.reset();
    profile.details = {{QStringLiteral("hash"), QStringLiteral("sha256:0f1e")},
                       {QStringLiteral("changes"),
                        QJsonArray{QJsonObject{{QStringLiteral("code"), QStringLiteral("ST1")},
                                               {QStringLiteral("from"), 350},
                                               {QStringLiteral("to"), 360}}}}};
    QTest::newRow("profile apply, whole device") << profile;
    JournalEvent alarm = sampleEvent(3, kT0 + 9, 1);
    alarm.kind = JournalEvent::Kind::Alarm;
    alarm.severity = JournalEvent::Severity::Error;
    alarm.device = {};
    alarm.port.reset();
    alarm.details = {};
    alarm.text = QString();
    QTest::newRow("no device, no port, no details, no text") << alarm;
}

void TestJournal::everyFieldOfAnEventSurvivesTheRoundTrip() {
    QFETCH(JournalEvent, record);
    QUuid uid;
    {
        Journal journal(m_path, quickOptions());
        uid = journal.append(record);
        QVERIFY(journal.flush());
    }
    const QList<StoredEvent> events = allEvents(m_path);
    QCOMPARE(events.size(), 1);
    const StoredEvent &stored = events.first();
    QCOMPARE(stored.uid, uid);
    QCOMPARE(stored.record.kind, record.kind);
    QCOMPARE(stored.record.severity, record.severity);
    QCOMPARE(stored.record.device.key(), record.device.key());
    QCOMPARE(stored.record.port, record.port);
    QCOMPARE(stored.record.timeMs, record.timeMs);
    QCOMPARE(stored.record.text, record.text);
    QCOMPARE(stored.record.details, record.details);
    QVERIFY(stored.context.isEmpty());
}

void TestJournal::anEventWithoutATimeIsStampedWithTheWallClock() {
    JournalEvent e = sampleEvent(1, 0);
    const qint64 before = QDateTime::currentMSecsSinceEpoch();
    {
        Journal journal(m_path, quickOptions());
        journal.append(e);
        QVERIFY(journal.flush());
    }
    const qint64 after = QDateTime::currentMSecsSinceEpoch();
    const qint64 stamped = allEvents(m_path).value(0).record.timeMs;
    QVERIFY2(stamped >= before && stamped <= after, qPrintable(QString::number(stamped)));
}

void TestJournal::committedNamesEachDurableRecordByRowAndUniqueId() {
    Journal journal(m_path, quickOptions());
    QSignalSpy committed(&journal, &Journal::committed);
    QVERIFY(committed.isValid());
    QList<QUuid> jointUids;
    QList<QUuid> eventUids;
    for (int i = 0; i < 5; ++i) {
        jointUids.append(journal.append(sampleJoint(i, kT0 + i)));
        eventUids.append(journal.append(sampleEvent(i, kT0 + i)));
    }
    QVERIFY(journal.flush());
    QVERIFY(QTest::qWaitFor([&] {
        int events = 0;
        for (const QList<QVariant> &signal : committed)
            events += signal.at(0).value<Committed>().events.size();
        return events == 5;
    }));
    QList<journal::RecordId> joints;
    QList<journal::RecordId> events;
    for (const QList<QVariant> &signal : committed) {
        joints += signal.at(0).value<Committed>().joints;
        events += signal.at(0).value<Committed>().events;
    }
    QCOMPARE(joints.size(), 5);
    const QList<StoredJoint> stored = allJoints(m_path);
    QCOMPARE(stored.size(), 5);
    for (int i = 0; i < 5; ++i) {
        QCOMPARE(joints.at(i).uid, jointUids.at(i));
        QCOMPARE(events.at(i).uid, eventUids.at(i));
        QCOMPARE(stored.at(i).id, joints.at(i).id);
        QCOMPARE(stored.at(i).uid, jointUids.at(i));
        if (i > 0)
            QVERIFY(joints.at(i).id > joints.at(i - 1).id);
    }
    QCOMPARE(QSet<QUuid>(jointUids.begin(), jointUids.end()).size(), 5);
    QVERIFY(!jointUids.contains(eventUids.first()));
}

void TestJournal::theContextIsStampedUntilChangedAndItsChangeIsAnEvent() {
    const model::WorkContext first{QStringLiteral("WO-1"), QStringLiteral("SN-1"),
                                   QStringLiteral("Ana")};
    const model::WorkContext second{QStringLiteral("WO-2"), QString(), QStringLiteral("Ben")};
    {
        Journal journal(m_path, quickOptions());
        journal.append(sampleJoint(0, kT0));
        journal.setContext(first);
        QVERIFY(journal.context() == first);
        journal.append(sampleJoint(1, kT0 + 1));
        journal.append(sampleEvent(1, kT0 + 1));
        journal.setContext(first); // no change, no event
        journal.setContext(second);
        journal.append(sampleJoint(2, kT0 + 2));
        QVERIFY(journal.flush());
    }
    const QList<StoredJoint> joints = allJoints(m_path);
    QCOMPARE(joints.size(), 3);
    QVERIFY(joints.at(0).context.isEmpty());
    QVERIFY(joints.at(1).context == first);
    QVERIFY(joints.at(2).context == second);

    const QList<StoredEvent> events = allEvents(m_path);
    QList<StoredEvent> changes;
    for (const StoredEvent &e : events) {
        if (e.record.kind == JournalEvent::Kind::ContextChange)
            changes.append(e);
    }
    QCOMPARE(changes.size(), 2);
    QVERIFY(changes.at(0).context == first);
    QVERIFY(changes.at(1).context == second);
    const QJsonObject details = changes.at(1).record.details;
    QCOMPARE(details.value(QStringLiteral("from"))[QStringLiteral("work_order")].toString(),
             QStringLiteral("WO-1"));
    QCOMPARE(details.value(QStringLiteral("to"))[QStringLiteral("operator")].toString(),
             QStringLiteral("Ben"));
    QVERIFY(changes.at(1).record.text.contains(QStringLiteral("WO-2")));
}

void TestJournal::aJointOpenAcrossABoardChangeIsTheEarlierBoards() {
    const model::WorkContext first{QString(), QStringLiteral("SN-1"), QString()};
    const model::WorkContext second{QString(), QStringLiteral("SN-2"), QString()};
    {
        Journal journal(m_path, quickOptions());
        journal.setContext(first);
        const qint64 firstMs = QDateTime::currentMSecsSinceEpoch(); // SN-1 named by now
        QTest::qWait(20);
        const qint64 changeMs = QDateTime::currentMSecsSinceEpoch(); // SN-2 named after it
        journal.setContext(second);
        // Begun on SN-1, ended after the change.
        journal.append(sampleJoint(0, (firstMs + changeMs) / 2));
        journal.append(sampleJoint(1, changeMs + 1000)); // begun on SN-2
        // Begun longer before the change than a live joint can last: another clock's (a
        // recording played back), stamped with the context of the moment.
        journal.append(sampleJoint(2, changeMs - Journal::kJointSpanMs - 60'000));
        QVERIFY(journal.flush());
    }
    const QList<StoredJoint> joints = allJoints(m_path);
    QCOMPARE(joints.size(), 3);
    QMap<qint64, QString> boardOf;
    for (const StoredJoint &joint : joints)
        boardOf.insert(joint.record.startMs, joint.context.boardSerial);
    const QList<QString> boards = boardOf.values(); // by start: the replayed, SN-1's, SN-2's
    QCOMPARE(boards, (QList<QString>{QStringLiteral("SN-2"), QStringLiteral("SN-1"),
                                     QStringLiteral("SN-2")}));
}

void TestJournal::sentMarksTakeRecordsOutOfTheUnsentListInOrder() {
    Journal journal(m_path, quickOptions());
    for (int i = 0; i < 6; ++i) {
        journal.append(sampleJoint(i, kT0 + 1000 - i)); // start times against the append order
        journal.append(sampleEvent(i, kT0 + i));
    }
    QVERIFY(journal.flush());
    JournalReader reader;
    const auto opened = reader.open(m_path);
    QVERIFY2(opened, qPrintable(opened.error()));
    const auto unsent = reader.unsentJoints(0, 100);
    QVERIFY2(unsent, qPrintable(unsent.error()));
    QCOMPARE(unsent->size(), 6);
    for (int i = 1; i < 6; ++i)
        QVERIFY(unsent->at(i).id > unsent->at(i - 1).id);

    journal.markJointsSent({unsent->at(0).id, unsent->at(3).id});
    const auto events = reader.unsentEvents(0, 100);
    QVERIFY2(events, qPrintable(events.error()));
    journal.markEventsSent({events->at(5).id});
    QVERIFY(journal.flush());

    const auto after = reader.unsentJoints(0, 100);
    QVERIFY2(after, qPrintable(after.error()));
    QList<qint64> ids;
    for (const StoredJoint &j : *after)
        ids.append(j.id);
    QCOMPARE(ids, (QList<qint64>{unsent->at(1).id, unsent->at(2).id, unsent->at(4).id,
                                 unsent->at(5).id}));
    // Paging: after a row id, at most `limit`.
    const auto page = reader.unsentJoints(unsent->at(2).id, 1);
    QVERIFY2(page, qPrintable(page.error()));
    QCOMPARE(page->size(), 1);
    QCOMPARE(page->first().id, unsent->at(4).id);
    QCOMPARE(reader.unsentEvents(0, 100)->size(), 5);
    journal::JointFilter all;
    const auto joints = reader.joints(all);
    QVERIFY2(joints, qPrintable(joints.error()));
    QCOMPARE(
        std::count_if(joints->begin(), joints->end(), [](const StoredJoint &j) { return j.sent; }),
        2);
}

void TestJournal::closingWritesWhatIsQueuedAndLaterAppendsAreCountedLost() {
    QList<QUuid> uids;
    {
        Journal journal(m_path, quickOptions());
        for (int i = 0; i < 3000; ++i)
            uids.append(journal.append(sampleJoint(i, kT0 + i)));
        journal.close();
        QCOMPARE(journal.state(), JournalState::Closed);
        QCOMPARE(journal.lostCount(), 0);
        QSignalSpy lost(&journal, &Journal::recordsLost);
        QVERIFY(lost.isValid());
        QVERIFY(journal.append(sampleJoint(0, kT0)).isNull());
        QCOMPARE(journal.lostCount(), 1);
        QCOMPARE(lost.count(), 1);
        QCOMPARE(lost.first().at(0).toLongLong(), 1);
        QCOMPARE(lost.first().at(1).toString(), QStringLiteral("The journal is closed."));
        QVERIFY(!journal.setRetentionDays(30)); // refused: nothing left to tell or to break
        journal.markJointsSent({1});
    }
    const QList<StoredJoint> joints = allJoints(m_path);
    QCOMPARE(joints.size(), uids.size());
    QCOMPARE(joints.last().uid, uids.last());
}

void TestJournal::aRecordTheDatabaseRefusesIsCountedLostAndTheOthersAreKept() {
    Journal journal(m_path, quickOptions());
    QSignalSpy lost(&journal, &Journal::recordsLost);
    QVERIFY(lost.isValid());
    model::JointRecord broken = sampleJoint(1, kT0 + 1);
    broken.powerIntegral = std::numeric_limits<double>::quiet_NaN(); // SQLite stores NULL
    journal.append(sampleJoint(0, kT0));
    journal.append(broken);
    journal.append(sampleJoint(2, kT0 + 2));
    QVERIFY(journal.flush());
    QCOMPARE(journal.state(), JournalState::Ready);
    QCOMPARE(journal.lostCount(), 1);
    QVERIFY2(journal.lossReason().contains(m_path), qPrintable(journal.lossReason()));
    QVERIFY(QTest::qWaitFor([&] { return !lost.isEmpty(); }));
    QCOMPARE(lost.first().at(0).toLongLong(), 1);

    const QList<StoredJoint> joints = allJoints(m_path);
    QCOMPARE(joints.size(), 2);
    QCOMPARE(joints.at(0).record.startMs, kT0);
    QCOMPARE(joints.at(1).record.startMs, kT0 + 2);
    const QList<StoredEvent> events = allEvents(m_path);
    QCOMPARE(events.size(), 1);
    QCOMPARE(events.first().record.kind, JournalEvent::Kind::Journal);
    QCOMPARE(events.first().record.severity, JournalEvent::Severity::Error);
    QCOMPARE(events.first().record.details.value(QStringLiteral("lost")).toInt(), 1);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJournal)

} // namespace tst_journal
#include "tst_journal.moc"
