// The line service every front end opens: a workspace of demo lines kept in a real SQLite journal,
// judged by the shared joint limits (the limits file, a rule on top, a line's own), a session it
// does not own kept as well, and a joint still under way when the service finishes kept as
// incomplete.
#include "service/lineservice.h"
#include "testmain.h"

#include "journal/journalreader.h"
#include "model/joints/jointlimitsfile.h"
#include "model/live/telemetryrecorder.h"
#include "sim/simline.h"

#include "demosession.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_lineservice {

using namespace tipscope;
using namespace tipscope::model;

namespace {

WorkspaceLine demoLine(const QString &name) {
    WorkspaceLine line;
    line.name = name;
    line.session = testing::unpacedDemoSettings();
    return line;
}

// A joint on port 1 of the session's demo station, once the port can make one and the detector
// has seen the tip settle.
bool makeJoint(Session &session, int depthK, qint64 recoveryMs) {
    sim::SimLine *demo = session.demoLine();
    if (!demo || !QTest::qWaitFor([&] { return demo->station()->canMakeJoint(1); }, 20000))
        return false;
    QTest::qWait(int(JointDetector::kSettleMs) + 500);
    return demo->startJoint(1, depthK, recoveryMs).has_value();
}

QList<journal::StoredJoint> journaled(const QString &path) {
    journal::JournalReader reader;
    if (!reader.open(path))
        return {};
    const auto joints = reader.joints({});
    return joints ? joints.value() : QList<journal::StoredJoint>{};
}

} // namespace

class TestLineService : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void everyLineIsJournaledAndJudgedByTheSharedLimitsWithTheRuleOnTop();
    void aLineWithLimitsOfItsOwnIsJudgedByThem();
    void aKeptSessionIsJournaledUntilReleased();
    void aJointUnderWayWhenTheServiceFinishesIsKeptIncomplete();
    void aLimitsFileThatCannotBeReadIsSaidAndTheDefaultsJudge();
    void aReadingTheStationRefusesCostsOnlyItself_data();
    void aReadingTheStationRefusesCostsOnlyItself();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }
    // A journal of its own, and no limits file (the defaults judge).
    service::LineService::Options withoutLimitsFile(const QString &journal) const {
        service::LineService::Options options;
        options.journalPath = path(journal);
        options.limitsPath = path(QStringLiteral("none.json"));
        return options;
    }
    QTemporaryDir m_dir;
};

void TestLineService::everyLineIsJournaledAndJudgedByTheSharedLimitsWithTheRuleOnTop() {
    JointLimitRules file;
    file.add({1, {}, 60'000, 5, std::nullopt}); // any dip on port 1 is too deep by the file
    QVERIFY(saveJointLimits(path(QStringLiteral("limits.json")), file));
    service::LineService::Options options;
    options.journalPath = path(QStringLiteral("shared.sqlite"));
    options.limitsPath = path(QStringLiteral("limits.json"));
    options.extraRules = {{1, {}, 100, 200, std::nullopt}}; // ... but the rule allows 200 K
    service::LineService service;
    QVERIFY(service.start(options));
    QCOMPARE(service.sharedLimits().limitsFor(1, {}).maxDipK, 200);
    QSignalSpy ended(&service, &service::LineService::jointEnded);
    QVERIFY(ended.isValid());
    WorkspaceFile lines;
    lines.lines = {demoLine(QStringLiteral("a")), demoLine(QStringLiteral("b"))};
    service.openLines(lines);
    QCOMPARE(service.workspace().count(), 2);
    QVERIFY(makeJoint(*service.workspace().session(1), 40, 800));
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 10000);
    QCOMPARE(ended.first().at(0).toInt(), 1);
    const auto joint = ended.first().at(1).value<JointRecord>();
    QCOMPARE(joint.verdict, JointVerdict::SlowRecovery); // 0.8 s against the rule's 0.1 s
    QVERIFY(service.finish(5000));
    const QList<journal::StoredJoint> kept = journaled(options.journalPath);
    QCOMPARE(kept.size(), 1);
    QCOMPARE(kept.first().record.device, joint.device);
    QCOMPARE(kept.first().record.verdict, JointVerdict::SlowRecovery);
}

void TestLineService::aLineWithLimitsOfItsOwnIsJudgedByThem() {
    const service::LineService::Options options = withoutLimitsFile(QStringLiteral("own.sqlite"));
    service::LineService service;
    QVERIFY(service.start(options));
    WorkspaceLine line = demoLine(QStringLiteral("own"));
    JointLimitRules own;
    own.add({1, {}, std::nullopt, 10, std::nullopt});
    line.jointLimits = own;
    service.openLines({{line}});
    QSignalSpy ended(&service, &service::LineService::jointEnded);
    QVERIFY(makeJoint(*service.workspace().session(0), 40, 800));
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 10000);
    QCOMPARE(ended.first().at(1).value<JointRecord>().verdict, JointVerdict::TooDeep);
}

void TestLineService::aKeptSessionIsJournaledUntilReleased() {
    const service::LineService::Options options = withoutLimitsFile(QStringLiteral("kept.sqlite"));
    service::LineService service;
    QVERIFY(service.start(options));
    Session session;
    service.keep(session);
    QSignalSpy ended(&service, &service::LineService::jointEnded);
    QVERIFY(testing::connectUnpacedDemo(session));
    QVERIFY(makeJoint(session, 40, 600));
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 10000);
    QCOMPARE(ended.first().at(0).toInt(), -1);
    service.release(session);
    QSignalSpy direct(&session.joints(), &JointWatcher::jointEnded);
    QVERIFY(makeJoint(session, 40, 600));
    QTRY_VERIFY_WITH_TIMEOUT(!direct.isEmpty(), 10000);
    QVERIFY(service.finish(5000));
    QCOMPARE(journaled(options.journalPath).size(), 1); // the second came after the release
}

void TestLineService::aJointUnderWayWhenTheServiceFinishesIsKeptIncomplete() {
    const service::LineService::Options options =
        withoutLimitsFile(QStringLiteral("finish.sqlite"));
    service::LineService service;
    QVERIFY(service.start(options));
    service.openLines({{demoLine(QStringLiteral("f"))}});
    Session &session = *service.workspace().session(0);
    QVERIFY(makeJoint(session, 60, 8000));
    QTRY_VERIFY_WITH_TIMEOUT(session.scheduler().isBusy(session.station(), 1), 5000);
    QTest::qWait(500); // the heater answers
    QVERIFY(service.finish(5000));
    const QList<journal::StoredJoint> kept = journaled(options.journalPath);
    QCOMPARE(kept.size(), 1);
    QCOMPARE(kept.first().record.verdict, JointVerdict::Incomplete);
    QVERIFY(kept.first().record.recoveryBounded);
}

void TestLineService::aLimitsFileThatCannotBeReadIsSaidAndTheDefaultsJudge() {
    QFile broken(path(QStringLiteral("broken.json")));
    QVERIFY(broken.open(QIODevice::WriteOnly));
    broken.write("{ not json");
    broken.close();
    service::LineService::Options options;
    options.journalPath = path(QStringLiteral("broken.sqlite"));
    options.limitsPath = broken.fileName();
    service::LineService service;
    const auto started = service.start(options);
    QVERIFY(!started);
    QVERIFY2(started.error().contains(QStringLiteral("broken.json")), qPrintable(started.error()));
    QVERIFY(service.isStarted()); // the journal is open all the same
    QCOMPARE(service.sharedLimits().defaults(), JointLimits{});
}

void TestLineService::aReadingTheStationRefusesCostsOnlyItself_data() {
    QTest::addColumn<QByteArray>("command");
    QTest::newRow("transformer temperature") << QByteArray("TT0");
    QTest::newRow("transistor temperature") << QByteArray("QT1");
    QTest::newRow("connected tool") << QByteArray("CT1");
    QTest::newRow("port status") << QByteArray("PS1");
}

// A station without one of the optional readings answers it with NAK 00004 from the start: the
// value is shown as refused, and the samples, the charts' history and the joints of the port go
// on all the same.
void TestLineService::aReadingTheStationRefusesCostsOnlyItself() {
    QFETCH(QByteArray, command);
    service::LineService service;
    QVERIFY(service.start(
        withoutLimitsFile(QStringLiteral("refused-%1.sqlite").arg(QString::fromLatin1(command)))));
    QSignalSpy ended(&service, &service::LineService::jointEnded);
    service.openLines({{demoLine(QStringLiteral("refusing"))}});
    Session &session = *service.workspace().session(0);
    QVERIFY(session.demoLine());
    sim::SimFaults faults;
    faults.nakCode = 4;
    faults.nakFor = sim::NakScope::Command;
    faults.nakCommand = command;
    session.demoLine()->setFaults(faults);
    QTRY_VERIFY_WITH_TIMEOUT(session.station(), 20000);
    Parameter *refused = session.station()->parameter(command);
    QVERIFY(refused);
    QTRY_VERIFY_WITH_TIMEOUT(refused->isRefused(), 20000);
    QVERIFY(makeJoint(session, 40, 800));
    QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty(), 10000);
    QCOMPARE(ended.first().at(1).value<JointRecord>().port, 1);
    const TelemetryBuffer *samples =
        session.telemetry().buffer(TelemetryRecorder::keyOf(*session.station(), 1));
    QVERIFY(samples && samples->size() > 10);
    QVERIFY(refused->isRefused());
}

TIPSCOPE_TEST_GUILESS_MAIN(TestLineService)

} // namespace tst_lineservice
#include "tst_lineservice.moc"
