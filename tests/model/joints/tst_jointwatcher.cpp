// Joints found live: the demo station at work (a joint on port 1 every 15 s) through the real
// session, its telemetry and the watcher. Each joint names the device and port, is measured and
// judged; one outside its limits is also a warning in the event log, naming its port. And when
// every joint begun before a moment has ended, which is what a board's end waits for.
#include "model/joints/jointwatcher.h"
#include "model/session.h"
#include "sim/demoactivity.h"
#include "testmain.h"

#include "demosession.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_jointwatcher {

using namespace tipscope;
using namespace tipscope::model;

namespace {
// The first joint comes kJointOffsetMs into the session, the next kJointEveryMs later.
constexpr int kTwoJointsMs =
    sim::DemoActivity::kJointOffsetMs + 2 * sim::DemoActivity::kJointEveryMs + 10'000;
} // namespace

class TestJointWatcher : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theDemoStationsJointsAreFoundMeasuredAndJudged();
    void settledOnceReadPastAMomentWithNoJointBegunBefore();
    void oneStationsOpenJointLeavesAnotherSettled();
};

void TestJointWatcher::theDemoStationsJointsAreFoundMeasuredAndJudged() {
    Session session;
    QSignalSpy joints(&session.joints(), &JointWatcher::jointEnded);
    QVERIFY(joints.isValid());
    Session::Settings settings = testing::unpacedDemoSettings();
    settings.demoActivity = true;
    session.connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(session.state() == Session::State::Connected, 30000);
    StationModel *station = session.station();
    QVERIFY(station);

    QTRY_VERIFY_WITH_TIMEOUT(!joints.isEmpty(), kTwoJointsMs);
    const auto first = joints.first().first().value<JointRecord>();
    QCOMPARE(first.device, station->identity());
    QCOMPARE(first.port, 1);
    QCOMPARE(first.tool, station->port(1)->toolName());
    QVERIFY2(first.verdict == JointVerdict::Ok,
             qPrintable(QStringLiteral("%1, recovery %2 ms, dip %3 K, %4 ms long")
                            .arg(jointVerdictName(first.verdict))
                            .arg(first.recoveryMs.value_or(-1))
                            .arg(first.dipDepth)
                            .arg(first.durationMs)));
    QVERIFY(first.recoveryMs.has_value());
    QVERIFY2(*first.recoveryMs > 0 && *first.recoveryMs < 5000,
             qPrintable(QString::number(*first.recoveryMs)));
    QVERIFY2(first.dipDepth > 5, qPrintable(QString::number(first.dipDepth)));
    QVERIFY(first.powerPeak > 0 && first.powerIntegral > 0);

    // A limit for port 1's tool that the demo's joints break, beside a looser one for the port:
    // the tool's rule is the more specific, so the next joint is judged slow and logged.
    JointLimitRules rules;
    rules.add({1, {}, 60'000, std::nullopt, std::nullopt});
    rules.add({1, first.tool.toLower(), 1, std::nullopt, std::nullopt});
    session.joints().setRules(rules);
    QCOMPARE(session.joints().rules().limitsFor(1, first.tool).maxRecoveryMs, 1);
    const qsizetype before = joints.size();
    QTRY_VERIFY_WITH_TIMEOUT(joints.size() > before, kTwoJointsMs);
    const auto slow = joints.last().first().value<JointRecord>();
    QCOMPARE(slow.verdict, JointVerdict::SlowRecovery);
    const QList<Event> events = session.eventLog().events();
    const auto warning = std::find_if(events.cbegin(), events.cend(), [](const Event &e) {
        return e.text.startsWith(QStringLiteral("joint recovered slowly"));
    });
    QVERIFY(warning != events.cend());
    QCOMPARE(warning->port, 1);
    QCOMPARE(warning->severity, Event::Severity::Warning);
    QCOMPARE(warning->kind, Event::Kind::JointWarning);
}

// Readings every 100 ms on one port, written straight into the telemetry: a settled tip, a dip
// and its return.
void TestJointWatcher::settledOnceReadPastAMomentWithNoJointBegunBefore() {
    Telemetry telemetry;
    JointWatcher watcher(telemetry);
    QSignalSpy joints(&watcher, &JointWatcher::jointEnded);
    QObject owner;
    const TelemetryKey key = QStringLiteral("line/port1");
    (void)telemetry.ensureBuffer(key, {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                       QStringLiteral("power"), QStringLiteral("status")});
    watcher.watch(&owner, key, {DeviceIdentity(), 1, [] { return QStringLiteral("T245"); }, 0.1});
    constexpr qint64 kT0 = 1'700'000'000'000;
    qint64 t = kT0;
    const auto read = [&](int tip, int power) {
        (void)telemetry.append(key, t, {tip, 350, power * 10, 0}); // status 0: working
        telemetry.notifyNow();
        t += 100;
    };
    for (int i = 0; i < 40; ++i) // 4 s in the band: settled
        read(350, 10);
    QVERIFY(watcher.settledUntil(t - 100));
    QVERIFY(!watcher.settledUntil(t + 500)); // not read that far yet

    const qint64 dipMs = t;
    for (int tip : {330, 320, 325, 332, 338, 343}) // a joint under way
        read(tip, 90);
    QVERIFY(!watcher.settledUntil(dipMs + 100)); // it began before, and is open
    QVERIFY(joints.isEmpty());
    for (int i = 0; i < 30; ++i) // back in the band, past the tail its fit reads
        read(350, 20);
    QCOMPARE(joints.size(), 1);
    QVERIFY(watcher.settledUntil(dipMs + 100));
}

// Two stations on one line, read side by side: a joint under way on the first keeps the line
// and that station unsettled, not the second, whose board may end at once.
void TestJointWatcher::oneStationsOpenJointLeavesAnotherSettled() {
    Telemetry telemetry;
    JointWatcher watcher(telemetry);
    QObject owner;
    const DeviceIdentity working{QStringLiteral("line"), 1, QStringLiteral("DME-2C"),
                                 QStringLiteral("9996780")};
    const DeviceIdentity resting{QStringLiteral("line"), 2, QStringLiteral("DDE-2C"),
                                 QStringLiteral("9996780")};
    const DeviceIdentity elsewhere{QStringLiteral("other"), 1, QStringLiteral("DME-2C"),
                                   QStringLiteral("9996780")};
    const QList<TelemetryKey> keys{QStringLiteral("line/01/port1"),
                                   QStringLiteral("line/02/port1")};
    for (const TelemetryKey &key : keys)
        (void)telemetry.ensureBuffer(key, {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                           QStringLiteral("power"), QStringLiteral("status")});
    const auto tool = [] { return QStringLiteral("T245"); };
    watcher.watch(&owner, keys[0], {working, 1, tool, 0.1});
    watcher.watch(&owner, keys[1], {resting, 1, tool, 0.1});
    constexpr qint64 kT0 = 1'700'000'000'000;
    qint64 t = kT0;
    const auto read = [&](int workingTip) {
        (void)telemetry.append(keys[0], t, {workingTip, 350, 500, 0});
        (void)telemetry.append(keys[1], t, {350, 350, 100, 0});
        telemetry.notifyNow();
        t += 100;
    };
    for (int i = 0; i < 40; ++i)
        read(350);
    const qint64 dipMs = t;
    for (int tip : {330, 320, 325, 332})
        read(tip);
    QVERIFY(!watcher.settledUntil(dipMs + 100));
    QVERIFY(!watcher.settledUntil(dipMs + 100, working));
    QVERIFY(watcher.settledUntil(dipMs + 100, resting));
    // A device the watcher has no port of holds nothing up.
    QVERIFY(watcher.settledUntil(dipMs + 100, elsewhere));
    // Neither is settled past what it was read until.
    QVERIFY(!watcher.settledUntil(t + 500, resting));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJointWatcher)

} // namespace tst_jointwatcher
#include "tst_jointwatcher.moc"
