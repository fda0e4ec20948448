// A journal that cannot write says why, keeps what it can in memory, counts the rest lost with
// the reason, and never blocks the caller: a folder or file that cannot be created (tests may
// run as root, where a read-only mode bit stops nothing, so the paths are under /proc), a full
// journal (its size limit, the same SQLite error as a full disk) that catches up once pruning
// frees space, a damaged file left untouched, and a journal another program holds locked.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/journalreader.h"

#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <csignal>
#include <sys/resource.h>

namespace tst_journalerrors {

using namespace tipscope;
using namespace tipscope::testing;
using journal::Journal;
using journal::JournalEvent;
using journal::JournalReader;
using journal::JournalState;

namespace {

constexpr qint64 kDayMs = 24 * 3600 * 1000;

QSet<QUuid> storedUids(const QString &path) {
    JournalReader reader;
    if (const auto opened = reader.open(path); !opened)
        qFatal("%s", qPrintable(opened.error()));
    QSet<QUuid> uids;
    const auto joints = reader.joints({});
    for (const journal::StoredJoint &j : joints ? joints.value() : QList<journal::StoredJoint>())
        uids.insert(j.uid);
    return uids;
}

} // namespace

class TestJournalErrors : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aLocationThatCannotBeWrittenSaysSoAndAppendsWaitThenCountLost_data();
    void aLocationThatCannotBeWrittenSaysSoAndAppendsWaitThenCountLost();
    void aDamagedFileIsReportedAndLeftUntouched();
    void aFullJournalHoldsRecordsAndCatchesUpWhenPruningFreesSpace();
    void aJournalLockedByAnotherProgramCatchesUpWhenReleased();
    void aFileSizeLimitIsToldAsFullAndCaughtUpOnceLifted();
};

void TestJournalErrors::aLocationThatCannotBeWrittenSaysSoAndAppendsWaitThenCountLost_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("expected");
    QTest::newRow("folder") << QStringLiteral("/proc/tipscope-test/journal.sqlite")
                            << QStringLiteral(
                                   "Cannot create the folder /proc/tipscope-test for the journal.");
    QTest::newRow("file") << QStringLiteral("/proc/tipscope-journal.sqlite")
                          << QStringLiteral("The journal /proc/tipscope-journal.sqlite cannot be "
                                            "written: its folder or the file is read-only or not "
                                            "accessible.");
}

void TestJournalErrors::aLocationThatCannotBeWrittenSaysSoAndAppendsWaitThenCountLost() {
    QFETCH(QString, path);
    QFETCH(QString, expected);
    journal::JournalOptions options = quickOptions();
    options.backlogLimit = 3;
    Journal journal(path, options);
    QSignalSpy lost(&journal, &Journal::recordsLost);
    QVERIFY(lost.isValid());
    QVERIFY(waitOpened(journal));
    QCOMPARE(journal.state(), JournalState::Failed);
    QCOMPARE(journal.errorText(), expected);

    for (int i = 0; i < 3; ++i)
        QVERIFY(!journal.append(sampleJoint(i, kT0)).isNull());
    QVERIFY(!journal.flush()); // returns at once: nothing can be written
    QCOMPARE(journal.pendingCount(), 3);
    QCOMPARE(journal.lostCount(), 0);
    QVERIFY(journal.append(sampleJoint(3, kT0)).isNull());
    QVERIFY(journal.append(sampleEvent(4, kT0)).isNull());
    QCOMPARE(journal.lostCount(), 2);
    QCOMPARE(journal.lossReason(), expected);
    QCOMPARE(lost.count(), 2);
    QCOMPARE(lost.at(1).at(0).toLongLong(), 2);
    QCOMPARE(lost.at(1).at(1).toString(), expected);

    // Closing cannot write the three waiting either: they are lost too, and said so.
    journal.close();
    QCOMPARE(journal.lostCount(), 5);
    QVERIFY2(journal.lossReason().contains(expected), qPrintable(journal.lossReason()));
}

void TestJournalErrors::aDamagedFileIsReportedAndLeftUntouched() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    QByteArray garbage(16384, '\0');
    for (int i = 0; i < garbage.size(); ++i)
        garbage[i] = char((i * 131) % 251);
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(garbage);
    }
    const QString expected =
        QStringLiteral("The journal %1 is damaged or is not a journal; it was left untouched.")
            .arg(path);
    {
        Journal journal(path, quickOptions());
        QVERIFY(waitOpened(journal));
        QCOMPARE(journal.state(), JournalState::Failed);
        QCOMPARE(journal.errorText(), expected);
        QVERIFY(!journal.append(sampleJoint(0, kT0)).isNull());
        QTest::qWait(150); // a few retries
    }
    JournalReader reader;
    const auto opened = reader.open(path);
    QVERIFY(!opened);
    QCOMPARE(opened.error(), expected);
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), garbage);
}

void TestJournalErrors::aFullJournalHoldsRecordsAndCatchesUpWhenPruningFreesSpace() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    journal::JournalOptions options = quickOptions();
    options.maxSizeBytes = 256 * 1024;
    options.backlogLimit = 300;
    options.maxBatch = 100;
    Journal journal(path, options);
    QSignalSpy states(&journal, &Journal::stateChanged);
    QVERIFY(states.isValid());
    QVERIFY(waitOpened(journal));
    QCOMPARE(journal.state(), JournalState::Ready);

    // Two-year-old joints until the journal is full.
    const qint64 old = QDateTime::currentMSecsSinceEpoch() - 730 * kDayMs;
    int appended = 0;
    while (journal.state() == JournalState::Ready && appended < 100'000) {
        for (int i = 0; i < 50; ++i, ++appended)
            journal.append(sampleJoint(appended, old + appended));
        (void)journal.flush();
    }
    QCOMPARE(journal.state(), JournalState::Failed);
    QVERIFY2(journal.errorText().contains(QStringLiteral("cannot grow")),
             qPrintable(journal.errorText()));
    QVERIFY(journal.pendingCount() > 0);

    // Recent joints: some wait in memory, those beyond the backlog limit are lost.
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    QList<QUuid> kept;
    for (int i = 0; i < 400; ++i) {
        const QUuid uid = journal.append(sampleJoint(i, now + i));
        if (!uid.isNull())
            kept.append(uid);
    }
    const qint64 lost = journal.lostCount();
    QVERIFY(lost > 0);
    QVERIFY(!kept.isEmpty());
    QCOMPARE(journal.lossReason(), journal.errorText());

    // A shorter retention frees space; the journal writes what it held. (It may fill up again
    // between two pruning steps, so wait for the pruning to end.)
    QSignalSpy pruned(&journal, &Journal::pruned);
    QVERIFY(pruned.isValid());
    QVERIFY(journal.setRetentionDays(365));
    QVERIFY(pruned.wait(20000));
    QVERIFY(QTest::qWaitFor(
        [&] { return journal.state() == JournalState::Ready && journal.pendingCount() == 0; },
        20000));
    QVERIFY(journal.flush());
    QCOMPARE(journal.pendingCount(), 0);
    QCOMPARE(journal.lostCount(), lost);
    QCOMPARE(states.constLast().at(0).value<JournalState>(), JournalState::Ready);
    journal.close();

    const QSet<QUuid> stored = storedUids(path);
    for (const QUuid &uid : kept)
        QVERIFY2(stored.contains(uid), qPrintable(uid.toString()));
    JournalReader reader;
    const auto opened = reader.open(path);
    QVERIFY2(opened, qPrintable(opened.error()));
    journal::EventFilter filter;
    filter.kinds = {JournalEvent::Kind::Journal};
    const auto reports = reader.events(filter);
    QVERIFY2(reports, qPrintable(reports.error()));
    QCOMPARE(reports->size(), 1);
    QCOMPARE(reports->first().record.details.value(QStringLiteral("lost")).toInteger(), lost);
    QVERIFY(reports->first().record.text.contains(QStringLiteral("cannot grow")));
}

void TestJournalErrors::aJournalLockedByAnotherProgramCatchesUpWhenReleased() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    Journal journal(path, quickOptions());
    QVERIFY(waitOpened(journal));
    journal.append(sampleJoint(0, kT0));
    QVERIFY(journal.flush());

    RawDatabase other(path);
    QString error;
    QVERIFY2(other.execAll(QStringLiteral("BEGIN IMMEDIATE"), &error), qPrintable(error));
    // The writer waits for the lock; appending does not wait for the writer.
    QList<QUuid> uids;
    for (int i = 1; i <= 1000; ++i)
        uids.append(journal.append(sampleJoint(i, kT0 + i)));
    QVERIFY(journal.pendingCount() > 0);
    QVERIFY(QTest::qWaitFor([&] { return journal.state() == JournalState::Failed; }, 20000));
    QVERIFY2(journal.errorText().contains(QStringLiteral("locked by another program")),
             qPrintable(journal.errorText()));

    QVERIFY2(other.execAll(QStringLiteral("ROLLBACK"), &error), qPrintable(error));
    QVERIFY(QTest::qWaitFor([&] { return journal.state() == JournalState::Ready; }, 20000));
    QVERIFY(journal.flush());
    QCOMPARE(journal.lostCount(), 0);
    const QSet<QUuid> stored = storedUids(path);
    QCOMPARE(stored.size(), 1001);
    for (const QUuid &uid : uids)
        QVERIFY(stored.contains(uid));
}

// SQLite reports a write past the file size limit (as many a full disk) as a plain I/O error.
// The journal must still say that it cannot grow, hold its records as for a full disk, and
// write them once there is room again.
void TestJournalErrors::aFileSizeLimitIsToldAsFullAndCaughtUpOnceLifted() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    journal::JournalOptions options = quickOptions();
    options.maxBatch = 100;
    Journal journal(path, options);
    QVERIFY(waitOpened(journal));
    QCOMPARE(journal.state(), JournalState::Ready);

    rlimit before{};
    QVERIFY(::getrlimit(RLIMIT_FSIZE, &before) == 0);
    rlimit limited = before;
    limited.rlim_cur = rlim_t(QFileInfo(path).size() + 512 * 1024);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN); // the limit's signal; a disk sends none
    QVERIFY(::setrlimit(RLIMIT_FSIZE, &limited) == 0);
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    QList<QUuid> appended;
    while (journal.state() == JournalState::Ready && appended.size() < 100'000) {
        for (int i = 0; i < 50; ++i)
            appended.append(
                journal.append(sampleJoint(int(appended.size()), now + appended.size())));
        (void)journal.flush();
    }
    const JournalState whileLimited = journal.state();
    const journal::JournalProblem problem = journal.problem();
    const QString said = journal.errorText();
    QVERIFY(::setrlimit(RLIMIT_FSIZE, &before) == 0);
    std::signal(SIGXFSZ, oldHandler);

    QCOMPARE(whileLimited, JournalState::Failed);
    QVERIFY2(said.contains(QStringLiteral("cannot grow")), qPrintable(said));
    QCOMPARE(problem, journal::JournalProblem::Full);
    QVERIFY(QTest::qWaitFor(
        [&] { return journal.state() == JournalState::Ready && journal.pendingCount() == 0; },
        20000));
    QCOMPARE(journal.lostCount(), 0);
    journal.close();
    const QSet<QUuid> stored = storedUids(path);
    for (const QUuid &uid : std::as_const(appended))
        QVERIFY2(stored.contains(uid), qPrintable(uid.toString()));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJournalErrors)

} // namespace tst_journalerrors
#include "tst_journalerrors.moc"
