// The joints from the command line, end to end with the real binary: monitor finds the demo
// station's joints, judges them by the shared limits and --limit, keeps them in the journal with
// the work context; `joints` lists them afterwards, filtered, as text, CSV and JSON; `journal`
// shows what the journal holds and keeps its retention in the file.
#include "programrun.h"
#include "testmain.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

namespace tst_clijoints {

using namespace tipscope::testing;

namespace {
ProgramRun runCli(const QStringList &args, const QByteArray &input = {}) {
    QProcess p;
    p.start(binaryPath(QStringLiteral("tipscope-cli")), args);
    if (!input.isEmpty())
        p.write(input);
    p.closeWriteChannel();
    return finishProcess(p, 60000);
}

QStringList dataLines(const QString &out) {
    return out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

// Runs `statements` on the SQLite file at `path` past TipScope, as another program would.
bool sqlOn(const QString &path, const QStringList &statements) {
    bool ok = true;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), path);
        db.setDatabaseName(path);
        ok = db.open();
        for (const QString &statement : statements)
            ok = ok && db.exec(statement).lastError().type() == QSqlError::NoError;
        db.close();
    }
    QSqlDatabase::removeDatabase(path);
    return ok;
}

QByteArray sha256Of(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly)
               ? QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256)
               : QByteArray();
}
} // namespace

class TestCliJoints : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void monitorKeepsJudgedJointsThatJointsListsAfterwards();
    void theJournalCommandShowsWhatItHoldsAndStoresTheRetention();
    void theContextIsReadFromStandardInputAndABadLineChangesNothing();
    void limitsAreSetAndShownAndABadRuleIsRefused();
    void aMissingJournalIsAClearError();
    void reportsOpenACurrentJournalOnlyToReadIt();
    void eachKindOfJournalProblemHasItsOwnExitStatus_data();
    void eachKindOfJournalProblemHasItsOwnExitStatus();

private:
    QTemporaryDir m_dir;
    QString m_journal;
};

void TestCliJoints::initTestCase() {
    QVERIFY(m_dir.isValid());
    m_journal = m_dir.filePath(QStringLiteral("journal.sqlite"));
}

void TestCliJoints::monitorKeepsJudgedJointsThatJointsListsAfterwards() {
    const ProgramRun context = runCli({"context", "set", "--work-order", "WO-7", "--serial",
                                       "SN-42", "--operator", "ana", "--journal", m_journal});
    QCOMPARE(context.exitCode, 0);
    // The demo's joints recover in about 1.6 s: a 0.5 s limit for port 1 judges them slow.
    const ProgramRun monitor =
        runCli({"--demo-activity", "monitor", "--interval", "100", "--duration", "16", "--limit",
                "port=1,recovery=0.5", "--journal", m_journal});
    QVERIFY2(monitor.exitCode == 0, qPrintable(monitor.err));
    const QStringList jointLines = dataLines(monitor.out).filter(QStringLiteral("  joint P1 "));
    QVERIFY2(!jointLines.isEmpty(), qPrintable(monitor.out.right(2000)));
    QVERIFY2(jointLines.first().endsWith(QStringLiteral(" slow recovery")),
             qPrintable(jointLines.first()));

    const ProgramRun csv = runCli({"joints", "--csv", "--journal", m_journal});
    QCOMPARE(csv.exitCode, 0);
    const QStringList rows = dataLines(csv.out);
    QCOMPARE(rows.size(), jointLines.size() + 1);
    QVERIFY(rows.first().startsWith(QStringLiteral("ts,end,id,device,")));
    QVERIFY2(rows.at(1).contains(QStringLiteral(",1,T210,350,")), qPrintable(rows.at(1)));
    QVERIFY2(rows.at(1).contains(QStringLiteral(",slow recovery,WO-7,SN-42,ana,")),
             qPrintable(rows.at(1)));

    const ProgramRun json = runCli({"joints", "--json", "--journal", m_journal});
    const QJsonArray joints = QJsonDocument::fromJson(json.out.toUtf8()).array();
    QCOMPARE(joints.size(), jointLines.size());
    const QJsonObject first = joints.first().toObject();
    QCOMPARE(first.value(QStringLiteral("model")).toString(), QStringLiteral("DME-2C"));
    QCOMPARE(first.value(QStringLiteral("port")).toInt(), 1);
    QVERIFY(first.value(QStringLiteral("recovery_ms")).toDouble() > 500);
    QVERIFY(first.value(QStringLiteral("ts")).toString().endsWith(QLatin1Char('Z')));

    const auto count = [this](const QStringList &filter) {
        const ProgramRun r = runCli(QStringList{"joints", "--journal", m_journal} + filter);
        return r.exitCode == 0 ? dataLines(r.out).size() : -1;
    };
    QCOMPARE(count({"--verdict", "slow-recovery", "--port", "1", "--device", "DME-2C"}),
             jointLines.size());
    QCOMPARE(count({"--since", "1h", "--work-order", "WO-7"}), jointLines.size());
    QCOMPARE(count({"--verdict", "ok"}), 0);
    QCOMPARE(count({"--port", "2"}), 0);
    QCOMPARE(count({"--since", "2099-01-01"}), 0);
    QCOMPARE(count({"--work-order", "WO-8"}), 0);

    const ProgramRun badTime = runCli({"joints", "--since", "yesterday", "--journal", m_journal});
    QCOMPARE(badTime.exitCode, 1);
    QVERIFY2(badTime.err.contains(QStringLiteral("'yesterday' is not a time")),
             qPrintable(badTime.err));
    const ProgramRun badDevice = runCli({"joints", "--device", "HDE", "--journal", m_journal});
    QCOMPARE(badDevice.exitCode, 1);
    QVERIFY2(badDevice.err.contains(QStringLiteral("no device 'HDE'")), qPrintable(badDevice.err));
}

void TestCliJoints::theJournalCommandShowsWhatItHoldsAndStoresTheRetention() {
    const ProgramRun listed = runCli({"joints", "--csv", "--journal", m_journal});
    const qsizetype joints = dataLines(listed.out).size() - 1;
    QVERIFY(joints > 0);

    const ProgramRun shown = runCli({"journal", "--journal", m_journal});
    QVERIFY2(shown.exitCode == 0, qPrintable(shown.err));
    const QStringList lines = dataLines(shown.out);
    QCOMPARE(lines.first(), QStringLiteral("journal: ") + m_journal);
    QVERIFY2(lines.contains(QStringLiteral("joints: %1 (%1 unsent)").arg(joints)),
             qPrintable(shown.out));
    QVERIFY2(lines.contains(QStringLiteral("retention: 365 days")), qPrintable(shown.out));

    const ProgramRun set = runCli({"journal", "retention", "90", "--journal", m_journal});
    QVERIFY2(set.exitCode == 0, qPrintable(set.err));
    QCOMPARE(set.out.trimmed(), QStringLiteral("retention: 90 days"));

    const ProgramRun refused = runCli({"journal", "retention", "-5", "--journal", m_journal});
    QCOMPARE(refused.exitCode, 2);
    QVERIFY2(refused.err.contains(QStringLiteral("-5")), qPrintable(refused.err));
    const ProgramRun notANumber =
        runCli({"journal", "retention", "a-year", "--journal", m_journal});
    QCOMPARE(notANumber.exitCode, 1);

    const ProgramRun json = runCli({"journal", "--json", "--journal", m_journal});
    QCOMPARE(json.exitCode, 0);
    const QJsonObject summary = QJsonDocument::fromJson(json.out.toUtf8()).object();
    QCOMPARE(summary.value(QStringLiteral("retention_days")).toInt(), 90);
    QCOMPARE(summary.value(QStringLiteral("joints")).toInteger(), joints);
    QVERIFY(summary.value(QStringLiteral("oldest")).toString().endsWith(QLatin1Char('Z')));
    QVERIFY(summary.value(QStringLiteral("bytes")).toInteger() > 0);
}

void TestCliJoints::theContextIsReadFromStandardInputAndABadLineChangesNothing() {
    const QString journal = m_dir.filePath(QStringLiteral("stdin/journal.sqlite"));
    const ProgramRun set = runCli({"context", "set", "--stdin", "--journal", journal},
                                  "# from the MES\nwork_order=WO-9\nboard_serial=SN-1\n");
    QCOMPARE(set.exitCode, 0);
    QCOMPARE(dataLines(set.out),
             QStringList({"work_order=WO-9", "board_serial=SN-1", "operator="}));
    const ProgramRun bad =
        runCli({"context", "set", "--stdin", "--journal", journal}, "work_order=WO-10\nshift=2\n");
    QCOMPARE(bad.exitCode, 1);
    QVERIFY2(bad.err.contains(QStringLiteral("'shift=2' is not a context line")),
             qPrintable(bad.err));
    const ProgramRun shown = runCli({"context", "--journal", journal});
    QCOMPARE(dataLines(shown.out).first(), QStringLiteral("work_order=WO-9"));
    QCOMPARE(runCli({"context", "clear", "--journal", journal}).exitCode, 0);
    QCOMPARE(dataLines(runCli({"context", "--journal", journal}).out).first(),
             QStringLiteral("work_order="));
}

void TestCliJoints::limitsAreSetAndShownAndABadRuleIsRefused() {
    QCOMPARE(runCli({"limits", "set", "tool=C245,recovery=3.5,dip=60"}).exitCode, 0);
    const ProgramRun shown = runCli({"limits"});
    QCOMPARE(shown.exitCode, 0);
    QVERIFY2(shown.out.contains(QStringLiteral("rule tool=C245,recovery=3.5,dip=60")),
             qPrintable(shown.out));
    const ProgramRun bad = runCli({"limits", "set", "port=7,recovery=2"});
    QCOMPARE(bad.exitCode, 2);
    QVERIFY2(bad.err.contains(QStringLiteral("a port is a number from 1 to 4")),
             qPrintable(bad.err));
    QCOMPARE(runCli({"limits"}).out, shown.out);
    QCOMPARE(runCli({"limits", "clear"}).exitCode, 0);
    QVERIFY(!runCli({"limits"}).out.contains(QStringLiteral("rule ")));
}

void TestCliJoints::aMissingJournalIsAClearError() {
    const QString missing = m_dir.filePath(QStringLiteral("none/journal.sqlite"));
    const ProgramRun r = runCli({"joints", "--journal", missing});
    QCOMPARE(r.exitCode, 6);
    QVERIFY2(r.err.contains(missing), qPrintable(r.err));
}

void TestCliJoints::reportsOpenACurrentJournalOnlyToReadIt() {
    // Issue 38: a journal that can be read but not written (a read-only mount, the service's
    // journal read by a technician) could not be read at all, as the reader set it up to write.
    // A file in rollback mode shows it: setting it up for writing turns it to WAL.
    const QString path = m_dir.filePath(QStringLiteral("read-only/journal.sqlite"));
    QCOMPARE(runCli({"journal", "retention", "30", "--journal", path}).exitCode, 0);
    QVERIFY(sqlOn(path, {QStringLiteral("PRAGMA journal_mode = DELETE")}));
    const QByteArray before = sha256Of(path);
    QVERIFY(!before.isEmpty());
    const ProgramRun show = runCli({"journal", "show", "--journal", path});
    QVERIFY2(show.exitCode == 0, qPrintable(show.err));
    QVERIFY2(show.out.contains(QStringLiteral("retention: 30 days")), qPrintable(show.out));
    const ProgramRun joints = runCli({"joints", "--journal", path});
    QVERIFY2(joints.exitCode == 0, qPrintable(joints.err));
    QCOMPARE(sha256Of(path), before);
    QVERIFY(!QFile::exists(path + QStringLiteral("-wal")));
}

void TestCliJoints::eachKindOfJournalProblemHasItsOwnExitStatus_data() {
    // `joints` and `journal show` run the same open and integrity check, so they agree.
    QTest::addColumn<QString>("kind");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    QTest::newRow("missing") << QStringLiteral("missing") << 6
                             << QStringLiteral("There is no journal");
    QTest::newRow("damaged inside") << QStringLiteral("damaged") << 7 << QStringLiteral("damaged");
    QTest::newRow("not a journal")
        << QStringLiteral("text") << 7 << QStringLiteral("is damaged or is not a journal");
    QTest::newRow("another program's database")
        << QStringLiteral("foreign") << 7 << QStringLiteral("is not a TipScope journal");
    QTest::newRow("from a newer TipScope")
        << QStringLiteral("newer") << 8 << QStringLiteral("written by a newer TipScope");
}

void TestCliJoints::eachKindOfJournalProblemHasItsOwnExitStatus() {
    QFETCH(QString, kind);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    const QString path = m_dir.filePath(kind + QStringLiteral("/journal.sqlite"));
    QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
    if (kind == QLatin1String("text")) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly) && f.write(QByteArray(8192, 'j')) == 8192);
    } else if (kind == QLatin1String("foreign")) {
        QVERIFY(sqlOn(path, {QStringLiteral("CREATE TABLE recipes (name TEXT)")}));
    } else if (kind != QLatin1String("missing")) {
        QCOMPARE(runCli({"journal", "retention", "30", "--journal", path}).exitCode, 0);
        if (kind == QLatin1String("newer"))
            QVERIFY(sqlOn(path, {QStringLiteral("PRAGMA user_version = 99")}));
    }
    if (kind == QLatin1String("damaged")) {
        // Every page but the first (the header and the list of tables) overwritten.
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadWrite) && f.size() > 8192);
        QVERIFY(f.seek(4096));
        QVERIFY(f.write(QByteArray(int(f.size()) - 4096, '\xa5')) > 0);
    }
    for (const QStringList &command : {QStringList{"joints"}, QStringList{"journal", "show"}}) {
        const ProgramRun r = runCli(command + QStringList{"--journal", path});
        QVERIFY2(r.exitCode == exitCode, qPrintable(QStringLiteral("%1: exit %2: %3")
                                                        .arg(command.join(QLatin1Char(' ')))
                                                        .arg(r.exitCode)
                                                        .arg(r.err)));
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCliJoints)

} // namespace tst_clijoints
#include "tst_clijoints.moc"
