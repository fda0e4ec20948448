// The board record against what the journal holds: a journal written by the journal's own
// writer (writeSampleBoard), then read back as one board's record: its joints and only its, its
// events and those of its station while it was made, its result from the verdicts, each tip's
// wear replayed from the joints before it, the profile applied before it.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/boardrecord.h"
#include "journal/journalreader.h"

#include <QTemporaryDir>
#include <QTest>

namespace tst_boardrecord {

using namespace tipscope;
using namespace tipscope::testing;
using journal::BoardResult;
using journal::JournalEvent;
using model::JointVerdict;

class TestBoardRecord : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void theRecordHoldsTheBoardsJointsInTimeOrderAndNoOthers();
    void theResultFollowsTheWorstVerdict();
    void eventsAreTheBoardsAndItsStationsWhileItWasMade();
    void eachTipsWearIsReplayedFromItsJointsSinceTheToolChange();
    void theProfileAppliedBeforeTheBoardIsNamed();
    void theWorstJointsComeFailedFirstThenSlowest();
    void anUnknownSerialGivesAnEmptyRecord();

private:
    QTemporaryDir m_dir;
    SampleBoard m_sample;
    journal::JournalReader m_reader;
    journal::BoardRecord m_record;
};

void TestBoardRecord::initTestCase() {
    QVERIFY(m_dir.isValid());
    const QString path = m_dir.filePath(QStringLiteral("journal.sqlite"));
    m_sample = writeSampleBoard(path);
    QVERIFY(m_sample.written);
    const auto opened = m_reader.open(path);
    QVERIFY2(opened, qPrintable(opened.error()));
    const auto record = journal::buildBoardRecord(m_reader, QStringLiteral("SN-42"));
    QVERIFY2(record, qPrintable(record.error()));
    m_record = record.value();
}

void TestBoardRecord::theRecordHoldsTheBoardsJointsInTimeOrderAndNoOthers() {
    QCOMPARE(m_record.serial, QStringLiteral("SN-42"));
    QCOMPARE(m_record.joints.size(), m_sample.joints.size());
    for (int i = 0; i < m_sample.joints.size(); ++i) {
        QCOMPARE(m_record.joints.at(i).record, m_sample.joints.at(i));
        QCOMPARE(m_record.joints.at(i).context.boardSerial, QStringLiteral("SN-42"));
        QVERIFY(!m_record.joints.at(i).uid.isNull());
    }
    QCOMPARE(m_record.firstMs, m_sample.joints.first().startMs);
    QCOMPARE(m_record.lastMs, m_sample.joints.last().endMs);
    QCOMPARE(m_record.workOrders, QStringList{QStringLiteral("WO-7")});
    // The other line's work order and operator are on an event of the station, not the board's.
    QCOMPARE(m_record.operators, QStringList{QStringLiteral("ana")});
}

void TestBoardRecord::theResultFollowsTheWorstVerdict() {
    QCOMPARE(m_record.verdicts.value(JointVerdict::Ok), 3);
    QCOMPARE(m_record.verdicts.value(JointVerdict::SlowRecovery), 1);
    QCOMPARE(m_record.verdicts.value(JointVerdict::Incomplete), 1);
    QCOMPARE(m_record.verdicts.value(JointVerdict::TooDeep), 1);
    QCOMPARE(m_record.result, BoardResult::Fail);
    QCOMPARE(journal::boardResultName(m_record.result), QStringLiteral("fail"));
}

void TestBoardRecord::eventsAreTheBoardsAndItsStationsWhileItWasMade() {
    QList<JournalEvent> events;
    for (const journal::StoredEvent &e : m_record.events)
        events.append(e.record);
    QCOMPARE(events, m_sample.events);
    QCOMPARE(m_record.events.at(1).context.boardSerial, QStringLiteral("SN-99"));
}

void TestBoardRecord::eachTipsWearIsReplayedFromItsJointsSinceTheToolChange() {
    QCOMPARE(m_record.tips.size(), 2);
    const journal::BoardTip &c245 = m_record.tips.at(0);
    QCOMPARE(c245.port, 1);
    QCOMPARE(c245.tool, QStringLiteral("C245"));
    QCOMPARE(c245.joints, 5);
    QCOMPARE(c245.setpoints, QList<int>{350});
    QCOMPARE(c245.sinceMs, kT0);
    QCOMPARE(c245.historyJoints, m_sample.tipJointsBefore + 5);
    QCOMPARE(c245.baselineMs, 1000);
    // The last ten recovered and judged: two at 1.0 s before the board, three at 1.3 s and one
    // at 6.0 s on it (the incomplete one does not count): median 1.3 s.
    QCOMPARE(c245.recentMs, 1300);
    const journal::BoardTip &c210 = m_record.tips.at(1);
    QCOMPARE(c210.port, 2);
    QCOMPARE(c210.joints, 1);
    QCOMPARE(c210.sinceMs, 0);
    QCOMPARE(c210.historyJoints, 1);
    QVERIFY(!c210.baselineMs);
}

void TestBoardRecord::theProfileAppliedBeforeTheBoardIsNamed() {
    QCOMPARE(m_record.profilesBefore.size(), 1);
    QCOMPARE(m_record.profilesBefore.first().record, m_sample.profileBefore);
}

void TestBoardRecord::theWorstJointsComeFailedFirstThenSlowest() {
    const auto worst = journal::worstJoints(m_record, 3);
    QCOMPARE(worst.size(), 3);
    QCOMPARE(worst.at(0).record.verdict, JointVerdict::TooDeep);
    QCOMPARE(worst.at(1).record.verdict, JointVerdict::SlowRecovery);
    QCOMPARE(worst.at(2).record.verdict, JointVerdict::Incomplete);
    QCOMPARE(journal::worstJoints(m_record, 100).size(), m_record.joints.size());
}

void TestBoardRecord::anUnknownSerialGivesAnEmptyRecord() {
    const auto record = journal::buildBoardRecord(m_reader, QStringLiteral("SN-404"));
    QVERIFY2(record, qPrintable(record.error()));
    QVERIFY(record->isEmpty());
    QCOMPARE(record->result, BoardResult::NoJoints);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestBoardRecord)

} // namespace tst_boardrecord
#include "tst_boardrecord.moc"
