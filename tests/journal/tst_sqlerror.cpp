// How the journal tells a failed SQLite call: each of SQLite's result codes (extended ones too,
// as Qt reports them) becomes a sentence naming the file and a kind of problem; only what the
// record itself breaks is the record's error (counted lost, never retried); and a plain I/O error
// on a journal that stands at the process's file size limit is told as full, as that is its cure.
#include "journal/sqlerror.h"
#include "testmain.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <sys/resource.h>

namespace tst_sqlerror {

using namespace tipscope::journal;

namespace {
QSqlError sqliteError(int code) {
    return QSqlError(QStringLiteral("driver text"), QStringLiteral("database text"),
                     QSqlError::StatementError, QString::number(code));
}
const QString kPath = QStringLiteral("/data/journal.sqlite");
} // namespace

class TestSqlError : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void eachResultCodeIsToldWithTheFileAndItsKindOfProblem_data() {
        QTest::addColumn<int>("code");
        QTest::addColumn<JournalProblem>("problem");
        QTest::addColumn<QString>("text");
        const QString locked = QStringLiteral("The journal %1 is locked by another program.");
        const QString readOnly = QStringLiteral(
            "The journal %1 cannot be written: its folder or the file is read-only or not "
            "accessible.");
        const QString damaged =
            QStringLiteral("The journal %1 is damaged or is not a journal; it was left untouched.");
        QTest::newRow("busy") << 5 << JournalProblem::Locked << locked;
        QTest::newRow("busy, recovering (extended)")
            << (5 | 1 << 8) << JournalProblem::Locked << locked;
        QTest::newRow("locked") << 6 << JournalProblem::Locked << locked;
        QTest::newRow("read-only") << 8 << JournalProblem::ReadOnly << readOnly;
        QTest::newRow("cannot open") << 14 << JournalProblem::ReadOnly << readOnly;
        QTest::newRow("permission") << 3 << JournalProblem::ReadOnly << readOnly;
        QTest::newRow("corrupt") << 11 << JournalProblem::Damaged << damaged;
        QTest::newRow("not a database") << 26 << JournalProblem::Damaged << damaged;
        QTest::newRow("full") << 13 << JournalProblem::Full
                              << QStringLiteral("The journal %1 cannot grow: the disk is full or "
                                                "the journal reached its size limit.");
        QTest::newRow("a write failed (extended I/O error)")
            << (10 | 3 << 8) << JournalProblem::DiskError
            << QStringLiteral("The disk holding the journal %1 reported an error.");
        QTest::newRow("anything else") << 1 << JournalProblem::Other
                                       << QStringLiteral("The journal %1 reported an error: "
                                                         "database text driver text");
    }
    void eachResultCodeIsToldWithTheFileAndItsKindOfProblem() {
        QFETCH(int, code);
        QFETCH(JournalProblem, problem);
        QFETCH(QString, text);
        QCOMPARE(problemOf(sqliteError(code), kPath), problem);
        QCOMPARE(describeSqlError(sqliteError(code), kPath), text.arg(kPath));
        QVERIFY(!isRecordError(sqliteError(code)));
    }

    void onlyWhatTheRecordBreaksIsTheRecordsError_data() {
        QTest::addColumn<int>("code");
        QTest::newRow("constraint") << 19;
        QTest::newRow("unique constraint (extended)") << (19 | 8 << 8);
        QTest::newRow("not null constraint (extended)") << (19 | 5 << 8);
        QTest::newRow("type mismatch") << 20;
        QTest::newRow("too big") << 18;
    }
    void onlyWhatTheRecordBreaksIsTheRecordsError() {
        QFETCH(int, code);
        QVERIFY(isRecordError(sqliteError(code)));
    }

    void aCodeQtCouldNotReadIsNeitherTheRecordsNorAKnownProblem() {
        const QSqlError error(QStringLiteral("x"), QStringLiteral("y"), QSqlError::UnknownError,
                              QString());
        QVERIFY(!isRecordError(error));
        QCOMPARE(problemOf(error, kPath), JournalProblem::Other);
    }

    // The file size limit of the process (ulimit -f) makes a write fail with a plain I/O error;
    // a journal that stands within a page of it is full, not broken.
    void anIoErrorAtTheFileSizeLimitIsToldAsFull() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        QVERIFY(file.write(QByteArray(10'000, 'j')) == 10'000);
        file.close();
        const QSqlError ioError = sqliteError(10);
        QCOMPARE(problemOf(ioError, path), JournalProblem::DiskError);

        rlimit before{};
        QCOMPARE(::getrlimit(RLIMIT_FSIZE, &before), 0);
        rlimit tight = before;
        tight.rlim_cur = 40'000; // under the file and a page of SQLite's
        QCOMPARE(::setrlimit(RLIMIT_FSIZE, &tight), 0);
        const JournalProblem atLimit = problemOf(ioError, path);
        const QString told = describeSqlError(ioError, path);
        tight.rlim_cur = 10'000'000; // far above it
        QCOMPARE(::setrlimit(RLIMIT_FSIZE, &tight), 0);
        const JournalProblem farBelow = problemOf(ioError, path);
        QCOMPARE(::setrlimit(RLIMIT_FSIZE, &before), 0);

        QCOMPARE(atLimit, JournalProblem::Full);
        QVERIFY2(told.contains(QStringLiteral("cannot grow")), qPrintable(told));
        QCOMPARE(farBelow, JournalProblem::DiskError);
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestSqlError)

} // namespace tst_sqlerror

#include "tst_sqlerror.moc"
