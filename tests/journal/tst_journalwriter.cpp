// JournalWriter, the journal's one writer, driven directly in the test's own thread on a real
// SQLite file: what one transaction holds and in what order it is made durable, and a location
// that cannot be written holding every record until the writer is closed, which counts them lost
// and says why.
#include "journal/journalshared.h"
#include "journal/journalwriter.h"
#include "journalfixture.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_journalwriter {

using namespace tipscope;
using namespace tipscope::journal;
using namespace tipscope::testing;

namespace {
// What a Journal shares with its writer, as the Journal sets it up for `options`.
std::shared_ptr<JournalShared> sharedFor(const JournalOptions &options) {
    auto shared = std::make_shared<JournalShared>();
    shared->retentionDays = options.retentionDays.value_or(kDefaultRetentionDays);
    return shared;
}

PendingJoint pending(int i) {
    return {QUuid::createUuid(), model::WorkContext{}, sampleJoint(i, kT0 + i * 1000)};
}

void queue(JournalShared &shared, const QList<PendingJoint> &joints) {
    QMutexLocker lock(&shared.mutex);
    for (const PendingJoint &j : joints) {
        shared.queue.push_back(j);
        ++shared.appended;
    }
}

// The joints of every `committed` signal, in the order they were made durable.
QList<RecordId> committedJoints(const QSignalSpy &spy) {
    QList<RecordId> all;
    for (const QList<QVariant> &signal : spy)
        all += signal.at(0).value<Committed>().joints;
    return all;
}
} // namespace

class TestJournalWriter : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void eachTransactionHoldsAtMostABatchAndSaysWhatItMadeDurable();
    void aLocationThatCannotBeWrittenHoldsEveryRecordUntilClosedThenCountsThemLost();
};

void TestJournalWriter::eachTransactionHoldsAtMostABatchAndSaysWhatItMadeDurable() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    JournalOptions options = quickOptions(); // nothing pruned: the joints are of 2023
    options.maxBatch = 2;
    const auto shared = sharedFor(options);
    JournalWriter writer(shared, path, options);
    QSignalSpy committed(&writer, &JournalWriter::committed);
    QVERIFY(committed.isValid());
    QList<PendingJoint> joints;
    for (int i = 0; i < 5; ++i)
        joints.append(pending(i));
    queue(*shared, joints);

    writer.start();

    QCOMPARE(committed.count(), 3);
    const QList<int> sizes = {2, 2, 1};
    for (int i = 0; i < committed.count(); ++i)
        QCOMPARE(committed.at(i).at(0).value<Committed>().joints.size(), sizes.at(i));
    const QList<RecordId> ids = committedJoints(committed);
    QCOMPARE(ids.size(), joints.size());
    for (int i = 0; i < ids.size(); ++i) {
        QCOMPARE(ids.at(i).uid, joints.at(i).uid);
        if (i > 0)
            QVERIFY(ids.at(i).id > ids.at(i - 1).id);
    }
    {
        QMutexLocker lock(&shared->mutex);
        QCOMPARE(shared->state, JournalState::Ready);
        QCOMPARE(shared->handled, quint64(5));
        QCOMPARE(shared->held, 0);
        QCOMPARE(shared->lost, 0);
    }
    writer.close(); // the writer keeps the file to itself while it is open
    QCOMPARE(shared->lost, 0);
    RawDatabase raw(path);
    QVERIFY(raw.isOpen());
    QCOMPARE(raw.scalar(QStringLiteral("SELECT COUNT(*) FROM joints")).toInt(), 5);
    QCOMPARE(raw.scalar(QStringLiteral("SELECT MIN(start_ms) FROM joints")).toLongLong(), kT0);
}

void TestJournalWriter::
    aLocationThatCannotBeWrittenHoldsEveryRecordUntilClosedThenCountsThemLost() {
    const auto shared = sharedFor(quickOptions());
    const QString path = QStringLiteral("/proc/tipscope-journal.sqlite");
    JournalWriter writer(shared, path, quickOptions());
    QSignalSpy committed(&writer, &JournalWriter::committed);
    QSignalSpy lost(&writer, &JournalWriter::recordsLost);
    QVERIFY(committed.isValid() && lost.isValid());
    writer.start();
    {
        QMutexLocker lock(&shared->mutex);
        QCOMPARE(shared->state, JournalState::Failed);
        QVERIFY2(shared->errorText.contains(path), qPrintable(shared->errorText));
    }
    queue(*shared, {pending(0), pending(1)});
    writer.drain();
    queue(*shared, {pending(2)});
    writer.drain();
    {
        QMutexLocker lock(&shared->mutex);
        QCOMPARE(shared->held, 3);
        QCOMPARE(shared->handled, quint64(3)); // dealt with: held, so flush() does not wait
        QCOMPARE(shared->lost, 0);
    }
    QCOMPARE(committed.count(), 0);
    QCOMPARE(lost.count(), 0);

    writer.close();

    QCOMPARE(committed.count(), 0);
    QCOMPARE(lost.count(), 1);
    QCOMPARE(lost.at(0).at(0).toLongLong(), 3);
    QVERIFY2(lost.at(0).at(1).toString().contains(QStringLiteral("closed before it could write")),
             qPrintable(lost.at(0).at(1).toString()));
    QMutexLocker lock(&shared->mutex);
    QCOMPARE(shared->lost, 3);
    QCOMPARE(shared->held, 0);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJournalWriter)

} // namespace tst_journalwriter

#include "tst_journalwriter.moc"
