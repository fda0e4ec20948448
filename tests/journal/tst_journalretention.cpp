// Retention: records older than the retention are pruned (in small batches, the appends made
// meanwhile all kept), at opening and when the retention changes; a retention of 0 keeps all.
#include "journalfixture.h"

#include "journal/journalreader.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

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

} // namespace

class TestJournalRetention : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aShorterRetentionPrunesOldRecordsInBatchesWhileAppendsGoOn();
    void aJournalOpenedWithARetentionPrunesAtOnce();
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

    journal.setRetentionDays(365);
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

QTEST_GUILESS_MAIN(TestJournalRetention)
#include "tst_journalretention.moc"
