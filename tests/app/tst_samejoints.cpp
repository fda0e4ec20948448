// The same samples give the same joints in every front end: one recording of a 4-port station
// making joints is played as a workspace line by the window, by `tipscope-cli monitor --journal`
// and by tipscope-agent, and the three journals hold the same joints, field for field (device,
// port, tool, start, end, dip, recovery, verdict, uncertainty), none missing and none extra,
// each made joint found once.
#include "agentprocess.h"
#include "jointrecording.h"
#include "mainwindow.h"
#include "mosquittobroker.h"
#include "ptyfixtures.h"
#include "testmain.h"

#include "../mqtt/mqtttesting.h"

#include "journal/jointexport.h"
#include "journal/journalreader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace tst_samejoints {

using namespace tipscope;
using namespace tipscope::model;

namespace {

QList<JointRecord> jointsIn(const QString &journalPath) {
    journal::JournalReader reader;
    if (!reader.open(journalPath))
        return {};
    const auto stored = reader.joints({});
    QList<JointRecord> joints;
    if (stored)
        for (const journal::StoredJoint &j : stored.value())
            joints.append(j.record);
    std::sort(joints.begin(), joints.end(), [](const JointRecord &a, const JointRecord &b) {
        return std::tie(a.port, a.startMs) < std::tie(b.port, b.startMs);
    });
    return joints;
}

QString describe(const QList<JointRecord> &joints) {
    QStringList lines;
    for (const JointRecord &j : joints) {
        journal::StoredJoint stored;
        stored.record = j;
        lines.append(QString::fromUtf8(
            QJsonDocument(journal::jointJson(stored)).toJson(QJsonDocument::Compact)));
    }
    return lines.join(QLatin1Char('\n'));
}

// A front end of its own: its data and settings in a folder of the test's, not the user's.
QProcessEnvironment ownHome(const QString &folder) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_DATA_HOME"), folder + QStringLiteral("/data"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), folder + QStringLiteral("/config"));
    return env;
}

} // namespace

class TestSameJoints : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void theWindowTheCommandLineAndTheAgentJournalTheSameJoints();

private:
    // Each plays the workspace and puts what its journal holds in `joints`.
    void playInTheWindow(QList<JointRecord> *joints);
    void playInTheCommandLine(QList<JointRecord> *joints);
    void playInTheAgent(QList<JointRecord> *joints);

    testing::MosquittoBroker m_broker;
    QTemporaryDir m_dir;
    QString m_workspace;
    QJsonObject m_line;
    testing::RecordedJoints m_truth;
};

void TestSameJoints::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QFileInfo(journal::Journal::defaultPath()).dir().removeRecursively();
    TIPSCOPE_START_BROKER(m_broker);
    QVERIFY(m_dir.isValid());
    const QString recording = m_dir.filePath(QStringLiteral("joints.csv"));
    QString error;
    QVERIFY2(testing::writeJointRecording(recording, &m_truth, &error), qPrintable(error));
    m_line = {{QStringLiteral("name"), QStringLiteral("replayed")},
              {QStringLiteral("connection"),
               QJsonObject{{QStringLiteral("kind"), QStringLiteral("recording")},
                           {QStringLiteral("path"), recording}}}};
    m_workspace = m_dir.filePath(QStringLiteral("replay.json"));
    QFile file(m_workspace);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(
        QJsonDocument(QJsonObject{{QStringLiteral("format"), QStringLiteral("tipscope-workspace")},
                                  {QStringLiteral("version"), 1},
                                  {QStringLiteral("lines"), QJsonArray{m_line}}})
            .toJson());
}

void TestSameJoints::playInTheWindow(QList<JointRecord> *joints) {
    QString journalPath;
    {
        gui::MainWindow w;
        w.show();
        journalPath = w.journal().path();
        const QString refused = w.openWorkspace(m_workspace);
        QVERIFY2(refused.isEmpty(), qPrintable(refused));
        const Session *line = w.workspace().session(0);
        QTRY_VERIFY_WITH_TIMEOUT(line->state() == Session::State::Disconnected ||
                                     line->state() == Session::State::Failed,
                                 60'000);
        QCOMPARE(line->state(), Session::State::Disconnected);
        w.close(); // waits for the journal
    }
    *joints = jointsIn(journalPath);
}

void TestSameJoints::playInTheCommandLine(QList<JointRecord> *joints) {
    QProcess cli;
    cli.setProcessEnvironment(ownHome(m_dir.filePath(QStringLiteral("cli"))));
    const QString journalPath = m_dir.filePath(QStringLiteral("cli.sqlite"));
    cli.start(testing::binaryPath(QStringLiteral("tipscope-cli")),
              {QStringLiteral("--workspace"), m_workspace, QStringLiteral("monitor"),
               QStringLiteral("--journal"), journalPath});
    // It ends by itself once the recording is played.
    QVERIFY2(cli.waitForFinished(120'000),
             "tipscope-cli did not end once the recording was played");
    const QString said = QString::fromUtf8(cli.readAllStandardError());
    QVERIFY2(cli.exitStatus() == QProcess::NormalExit && cli.exitCode() == 0, qPrintable(said));
    QVERIFY2(said.contains(QStringLiteral("joints.csv played")), qPrintable(said));
    *joints = jointsIn(journalPath);
}

void TestSameJoints::playInTheAgent(QList<JointRecord> *joints) {
    testing::AgentProcess agent;
    agent.process().setProcessEnvironment(ownHome(agent.folder()));
    agent.configureLines({m_line}, m_broker.port());
    QString error;
    QVERIFY2(agent.start(&error), qPrintable(error));
    // A service goes on after the recording: stopped once the journal holds what it played.
    QTRY_COMPARE_WITH_TIMEOUT(jointsIn(agent.journalPath()).size(), m_truth.made.size(), 60'000);
    QVERIFY2(agent.stop() == 0, qPrintable(agent.log()));
    *joints = jointsIn(agent.journalPath());
}

void TestSameJoints::theWindowTheCommandLineAndTheAgentJournalTheSameJoints() {
    QList<JointRecord> window, cli, agent;
    playInTheWindow(&window);
    if (QTest::currentTestFailed())
        return;
    playInTheCommandLine(&cli);
    if (QTest::currentTestFailed())
        return;
    playInTheAgent(&agent);
    if (QTest::currentTestFailed())
        return;

    // Each made joint is found once, on its port.
    QCOMPARE(window.size(), m_truth.made.size());
    for (int port = 1; port <= 4; ++port)
        QCOMPARE(std::count_if(window.cbegin(), window.cend(),
                               [port](const JointRecord &j) { return j.port == port; }),
                 std::count_if(m_truth.made.cbegin(), m_truth.made.cend(),
                               [port](const sim::SimJoint &j) { return j.port == port; }));
    QVERIFY2(
        cli == window,
        qPrintable(
            QStringLiteral("window:\n%1\ncommand line:\n%2").arg(describe(window), describe(cli))));
    QVERIFY2(agent == window,
             qPrintable(
                 QStringLiteral("window:\n%1\nagent:\n%2").arg(describe(window), describe(agent))));
}

TIPSCOPE_TEST_MAIN(TestSameJoints)

} // namespace tst_samejoints
#include "tst_samejoints.moc"
