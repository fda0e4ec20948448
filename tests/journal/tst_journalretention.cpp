// Retention: records older than the retention are pruned (in small batches, the appends made
// meanwhile all kept), at opening and when the retention changes; a retention of 0 keeps all.
// The retention is kept in the journal file: every program that opens it prunes alike, and a
// running one takes a retention another program set at its next pruning.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/journalreader.h"
#include "journal/journalsettings.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_journalretention {

using namespace tipscope;
using namespace tipscope::testing;
using journal::Journal;
using journal::JournalReader;

namespace {

constexpr qint64 kDayMs = 24 * 3600 * 1000;

struct Counts {
    qint64 joints = -1;
    qint64 events = -1;
};

Counts countRecords(const QString &path) {
    JournalReader reader;
    if (!reader.open(path))
        return {};
    const auto events = reader.events({});
    const auto joints = reader.countJoints({});
    return {joints ? joints.value() : -1, events ? events->size() : -1};
}

// 40 joints and 30 events 400 days old, 10 joints and 5 events of today.
void appendOldAndNew(Journal &journal) {
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const qint64 old = now - 400 * kDayMs;
    for (int i = 0; i < 40; ++i)
        journal.append(sampleJoint(i, old + i));
    for (int i = 0; i < 30; ++i)
        journal.append(sampleEvent(i, old + i));
    for (int i = 0; i < 10; ++i)
        journal.append(sampleJoint(i, now - i));
    for (int i = 0; i < 5; ++i)
        journal.append(sampleEvent(i, now - i));
}

// A journal at `path` holding appendOldAndNew()'s records and `retentionDays` in its file.
bool writeOldAndNew(const QString &path, int retentionDays) {
    Journal journal(path, quickOptions());
    appendOldAndNew(journal);
    return journal.setRetentionDays(retentionDays) && journal.retentionDays() == retentionDays &&
           journal.flush();
}

} // namespace

class TestJournalRetention : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aShorterRetentionPrunesOldRecordsInBatchesWhileAppendsGoOn();
    void aJournalOpenedWithARetentionPrunesAtOnce();
    void theRetentionIsKeptInTheFileForEveryProgramThatOpensIt();
    void aRunningJournalTakesARetentionAnotherProgramSet();
    void anImpossibleRetentionIsRefusedAndChangesNothing();
};

void TestJournalRetention::aShorterRetentionPrunesOldRecordsInBatchesWhileAppendsGoOn() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    journal::JournalOptions options = quickOptions();
    options.pruneBatch = 7;
    Journal journal(path, options);
    QSignalSpy pruned(&journal, &Journal::pruned);
    QVERIFY(pruned.isValid());
    appendOldAndNew(journal);
    QVERIFY(journal.flush());
    QCOMPARE(countRecords(path).joints, 50); // retention 0 keeps everything

    QVERIFY(journal.setRetentionDays(365));
    for (int i = 0; i < 20; ++i)
        journal.append(sampleJoint(i, QDateTime::currentMSecsSinceEpoch()));
    QVERIFY(pruned.wait(10000));
    QCOMPARE(pruned.count(), 1);
    QCOMPARE(pruned.first().at(0).toLongLong(), 40);
    QCOMPARE(pruned.first().at(1).toLongLong(), 30);
    QVERIFY(journal.flush());
    const Counts left = countRecords(path);
    QCOMPARE(left.joints, 30);
    QCOMPARE(left.events, 5);
}

void TestJournalRetention::aJournalOpenedWithARetentionPrunesAtOnce() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    {
        Journal journal(path, quickOptions());
        appendOldAndNew(journal);
        QVERIFY(journal.flush());
    }
    QCOMPARE(countRecords(path).joints, 50);
    journal::JournalOptions options; // the default retention: a year
    Journal journal(path, options);
    QSignalSpy pruned(&journal, &Journal::pruned);
    QVERIFY(pruned.isValid());
    QVERIFY(pruned.wait(10000));
    QCOMPARE(pruned.first().at(0).toLongLong(), 40);
    QCOMPARE(pruned.first().at(1).toLongLong(), 30);
    const Counts left = countRecords(path);
    QCOMPARE(left.joints, 10);
    QCOMPARE(left.events, 5);
}

void TestJournalRetention::theRetentionIsKeptInTheFileForEveryProgramThatOpensIt() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    QVERIFY(writeOldAndNew(path, 500));
    // Opened without a retention of its own: the file's 500 days, not the default year, so the
    // 400-day-old records stay.
    {
        Journal journal(path);
        QVERIFY(waitOpened(journal));
        QCOMPARE(journal.retentionDays(), 500);
        QVERIFY(journal.flush());
    }
    QCOMPARE(countRecords(path).joints, 50);
    JournalReader reader;
    QVERIFY(reader.open(path));
    const auto summary = reader.summary();
    QVERIFY2(summary, qPrintable(summary ? QString() : summary.error()));
    QCOMPARE(summary->retentionDays, 500);
    QCOMPARE(summary->joints, 50);
    QCOMPARE(summary->events, 35);
    QCOMPARE(summary->unsentJoints, 50);
    QVERIFY(summary->oldestMs && summary->newestMs);
    QVERIFY(*summary->oldestMs < *summary->newestMs - 399 * kDayMs);
    QVERIFY(summary->fileBytes > 0);
}

void TestJournalRetention::aRunningJournalTakesARetentionAnotherProgramSet() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    QVERIFY(writeOldAndNew(path, 0));
    journal::JournalOptions options;
    options.pruneIntervalMs = 100;
    Journal running(path, options);
    QSignalSpy pruned(&running, &Journal::pruned);
    QVERIFY(pruned.isValid());
    QVERIFY(waitOpened(running));
    QCOMPARE(running.retentionDays(), 0);
    {
        Journal other(path, quickOptions()); // as `tipscope-cli journal retention 365` does
        QVERIFY(other.setRetentionDays(365));
        other.close(); // it prunes the old records itself
    }
    QCOMPARE(countRecords(path).joints, 10);
    QTRY_COMPARE_WITH_TIMEOUT(running.retentionDays(), 365, 10000);
    // The running journal now prunes by the year too.
    const qint64 old = QDateTime::currentMSecsSinceEpoch() - 400 * kDayMs;
    for (int i = 0; i < 5; ++i)
        running.append(sampleJoint(i, old + i));
    QVERIFY(running.flush());
    QVERIFY(pruned.wait(10000));
    QCOMPARE(pruned.last().at(0).toLongLong(), 5);
    QCOMPARE(countRecords(path).joints, 10);
}

void TestJournalRetention::anImpossibleRetentionIsRefusedAndChangesNothing() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    Journal journal(path);
    QVERIFY(waitOpened(journal));
    QCOMPARE(journal.retentionDays(), journal::kDefaultRetentionDays);
    for (const int days : {-1, journal::kMaxRetentionDays + 1}) {
        const auto set = journal.setRetentionDays(days);
        QVERIFY(!set);
        QVERIFY2(set.error().contains(QString::number(days)), qPrintable(set.error()));
    }
    QVERIFY(journal.flush());
    QCOMPARE(journal.retentionDays(), journal::kDefaultRetentionDays);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJournalRetention)

} // namespace tst_journalretention
#include "tst_journalretention.moc"
