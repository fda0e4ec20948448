// Crash safety: a writer appending as fast as it can is killed (SIGKILL) in the middle of its
// work, three times over on the same file. Each time the file passes PRAGMA integrity_check and
// holds every joint the writer had reported durable before it died.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/journalreader.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace tst_journalcrash {

using namespace tipscope;
using namespace tipscope::testing;

class TestJournalCrash : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyJointReportedDurableSurvivesAKill_data();
    void everyJointReportedDurableSurvivesAKill();

private:
    QTemporaryDir m_dir;
};

void TestJournalCrash::everyJointReportedDurableSurvivesAKill_data() {
    QTest::addColumn<int>("durableBeforeKill"); // ids to see printed before the kill
    QTest::newRow("early") << 500;
    QTest::newRow("later") << 5000;
    QTest::newRow("much later") << 20000;
}

void TestJournalCrash::everyJointReportedDurableSurvivesAKill() {
    QFETCH(int, durableBeforeKill);
    const QString path = m_dir.filePath(QStringLiteral("journal.sqlite")); // one file, all rows
    QProcess writer;
    writer.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    writer.start(QStringLiteral(JOURNAL_CRASH_WRITER), {path});
    QVERIFY2(writer.waitForStarted(), qPrintable(writer.errorString()));
    QByteArray output;
    const auto lines = [&] { return output.count('\n'); };
    QVERIFY(QTest::qWaitFor(
        [&] {
            output += writer.readAllStandardOutput();
            return lines() >= durableBeforeKill || writer.state() == QProcess::NotRunning;
        },
        60000));
    QCOMPARE(writer.state(), QProcess::Running); // still writing when killed
    writer.kill();                               // SIGKILL
    QVERIFY(writer.waitForFinished());
    QCOMPARE(writer.exitStatus(), QProcess::CrashExit);
    output += writer.readAllStandardOutput();

    // Only whole lines were reported; a line cut short by the kill names nothing.
    QList<QByteArray> reported = output.split('\n');
    reported.removeLast();
    QVERIFY(reported.size() >= durableBeforeKill);

    {
        RawDatabase raw(path);
        QCOMPARE(raw.scalar(QStringLiteral("PRAGMA integrity_check")).toString(),
                 QStringLiteral("ok"));
    }
    journal::JournalReader reader;
    const auto opened = reader.open(path);
    QVERIFY2(opened, qPrintable(opened.error()));
    const auto joints = reader.joints({});
    QVERIFY2(joints, qPrintable(joints.error()));
    QSet<QUuid> stored;
    for (const journal::StoredJoint &j : *joints)
        stored.insert(j.uid);
    int missing = 0;
    for (const QByteArray &line : reported)
        missing += stored.contains(QUuid(QString::fromLatin1(line))) ? 0 : 1;
    QCOMPARE(missing, 0);
    qInfo("%lld reported durable, %lld in the file", qint64(reported.size()),
          qint64(stored.size()));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJournalCrash)

} // namespace tst_journalcrash
#include "tst_journalcrash.moc"
