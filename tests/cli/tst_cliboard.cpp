// tipscope-cli board, end to end with the real binary, against a journal the journal's own
// writer wrote (writeSampleBoard): the record it prints holds what the journal holds for that
// board and nothing of other boards; --csv is `joints --csv` narrowed to the board; --pdf writes
// a PDF without a display; a missing journal, an unknown serial and bad arguments each end with
// their own status.
#include "journalfixture.h"
#include "programrun.h"
#include "testmain.h"

#include "journal/jointexport.h"
#include "journal/journalreader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

namespace tst_cliboard {

using namespace tipscope;
using namespace tipscope::testing;

namespace {
ProgramRun runBoardCli(const QStringList &args) {
    return runProgram(QStringLiteral("tipscope-cli"), args);
}
} // namespace

class TestCliBoard : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void theJsonRecordIsWhatTheJournalHoldsForTheBoard();
    void theCsvIsTheJointsOfTheBoardAsJointsWritesThem();
    void theTextSaysTheResultAndWhatIsNotInTheJournal();
    void aPdfIsWrittenWithoutADisplay();
    void anUnknownSerialAndBadArgumentsAreRefused_data();
    void anUnknownSerialAndBadArgumentsAreRefused();
    void aMissingJournalHasTheJournalsExitStatus();

private:
    QTemporaryDir m_dir;
    QString m_journal;
};

void TestCliBoard::initTestCase() {
    QVERIFY(m_dir.isValid());
    m_journal = m_dir.filePath(QStringLiteral("journal.sqlite"));
    QVERIFY(writeSampleBoard(m_journal).written);
}

void TestCliBoard::theJsonRecordIsWhatTheJournalHoldsForTheBoard() {
    const ProgramRun r = runBoardCli({"board", "SN-42", "--json", "--journal", m_journal});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QJsonObject board = QJsonDocument::fromJson(r.out.toUtf8()).object();
    QCOMPARE(board.value(QStringLiteral("board_serial")).toString(), QStringLiteral("SN-42"));
    QCOMPARE(board.value(QStringLiteral("result")).toString(), QStringLiteral("fail"));
    QVERIFY(!board.value(QStringLiteral("software")).toString().isEmpty());

    // What the journal holds, read past the command: every joint stamped SN-42, oldest first.
    journal::JournalReader reader;
    QVERIFY(reader.open(m_journal));
    journal::JointFilter all;
    all.order = journal::Order::OldestFirst;
    const auto joints = reader.joints(all);
    QVERIFY(joints);
    QJsonArray expected;
    for (const journal::StoredJoint &j : joints.value())
        if (j.context.boardSerial == QLatin1String("SN-42"))
            expected.append(journal::jointJson(j));
    QVERIFY(!expected.isEmpty());
    QCOMPARE(board.value(QStringLiteral("joints")).toArray(), expected);

    const QJsonArray events = board.value(QStringLiteral("events")).toArray();
    QStringList texts;
    for (const QJsonValue &e : events)
        texts.append(e.toObject().value(QStringLiteral("text")).toString());
    QVERIFY2(texts.contains(QStringLiteral("E-PT1: tip sensor open")), qPrintable(r.out));
    QVERIFY(!texts.contains(QStringLiteral("not the board's")));
}

void TestCliBoard::theCsvIsTheJointsOfTheBoardAsJointsWritesThem() {
    const ProgramRun board = runBoardCli({"board", "SN-42", "--csv", "--journal", m_journal});
    QVERIFY2(board.exitCode == 0, qPrintable(board.err));
    const ProgramRun joints = runBoardCli({"joints", "--csv", "--journal", m_journal});
    QCOMPARE(joints.exitCode, 0);
    const QStringList all = joints.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QStringList expected = all.filter(QStringLiteral(",SN-42,"));
    std::reverse(expected.begin(), expected.end()); // `joints` lists the newest first
    expected.prepend(all.first());
    QCOMPARE(board.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts), expected);
}

void TestCliBoard::theTextSaysTheResultAndWhatIsNotInTheJournal() {
    const ProgramRun r = runBoardCli({"board", "SN-42", "--journal", m_journal});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.startsWith(QStringLiteral("board SN-42\nresult: fail (6 joints:")),
             qPrintable(r.out));
    QVERIFY(r.out.contains(QStringLiteral("not in the journal:\n  limits: ")));
    QVERIFY(r.out.contains(QStringLiteral("recovery 0.8-1.8 s bounded")));
}

void TestCliBoard::aPdfIsWrittenWithoutADisplay() {
    const QString pdf = m_dir.filePath(QStringLiteral("SN-42.pdf"));
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    p.setProcessEnvironment(env);
    p.start(binaryPath(QStringLiteral("tipscope-cli")),
            {"board", "SN-42", "--pdf", pdf, "--journal", m_journal});
    const ProgramRun r = finishProcess(p, 60000);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
    QFile file(pdf);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray bytes = file.readAll();
    QVERIFY(bytes.startsWith("%PDF-"));
    QVERIFY(bytes.trimmed().endsWith("%%EOF"));
    // The sample board's few joints fit one page (the page tree says "/Type /Pages").
    QCOMPARE(bytes.count("/Type /Page") - bytes.count("/Type /Pages"), 1);

    const QString unwritable = m_dir.filePath(QStringLiteral("no/such/folder/SN-42.pdf"));
    const ProgramRun refused =
        runBoardCli({"board", "SN-42", "--pdf", unwritable, "--journal", m_journal});
    QCOMPARE(refused.exitCode, 1);
    QVERIFY2(refused.err.contains(QStringLiteral("cannot write")), qPrintable(refused.err));
}

void TestCliBoard::anUnknownSerialAndBadArgumentsAreRefused_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown serial")
        << QStringList{"board", "SN-404"} << QStringLiteral("the journal has no board 'SN-404'");
    QTest::newRow("no serial") << QStringList{"board"}
                               << QStringLiteral("board takes one board serial");
    QTest::newRow("two serials") << QStringList{"board", "SN-42", "SN-43"}
                                 << QStringLiteral("board takes one board serial");
    QTest::newRow("two formats") << QStringList{"board", "SN-42", "--json", "--csv"}
                                 << QStringLiteral("give one of --json, --csv and --pdf FILE");
    QTest::newRow("pdf without a file")
        << QStringList{"board", "SN-42", "--pdf"} << QStringLiteral("--pdf needs a value");
    QTest::newRow("an option of another command")
        << QStringList{"board", "SN-42", "--verdict", "ok"}
        << QStringLiteral("'board' has no option --verdict");
}

void TestCliBoard::anUnknownSerialAndBadArgumentsAreRefused() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    // The journal first: `--pdf` takes whatever follows it as its file.
    args.insert(1, m_journal);
    args.insert(1, QStringLiteral("--journal"));
    const ProgramRun r = runBoardCli(args);
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
}

void TestCliBoard::aMissingJournalHasTheJournalsExitStatus() {
    const QString missing = m_dir.filePath(QStringLiteral("none/journal.sqlite"));
    const ProgramRun r = runBoardCli({"board", "SN-42", "--journal", missing});
    QCOMPARE(r.exitCode, 6);
    QVERIFY2(r.err.contains(missing), qPrintable(r.err));
    QVERIFY(!QFile::exists(missing));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCliBoard)

} // namespace tst_cliboard
#include "tst_cliboard.moc"
