// The simulator makes ground truth: a joint asked for on a port (the joint command), a worn tip
// (wear) and random joints (--joints-per-minute) are found by the real JointDetector with the
// depth and recovery the simulator says it made. A bad command gets a clear error and changes
// nothing. The last test runs tipscope-sim itself and reads the joint it logs.
#include "model/joints/jointdetector.h"
#include "ptyfixtures.h"
#include "sim/simcontrol.h"
#include "sim/simline.h"
#include "testmain.h"

#include <QDateTime>
#include <QDeadlineTimer>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

namespace tst_simjoints {

using namespace tipscope;
using namespace tipscope::sim;
using namespace tipscope::model;

namespace {
constexpr int kStepMs = 20;
constexpr int kHeatUpMs = 10'000;

// A DME station whose ports are read every step as a client would, each by its own detector.
struct Bench {
    std::unique_ptr<SimLine> line = std::make_unique<SimLine>();
    SimStation *station = nullptr;
    std::vector<JointDetector> detectors;
    QList<JointRecord> found;

    Bench() {
        station = static_cast<SimStation *>(
            line->addDevice(std::make_unique<SimStation>(QStringLiteral("DME"))));
        for (int port = 1; port <= station->portCount(); ++port)
            detectors.emplace_back(DeviceIdentity{}, port);
        run(kHeatUpMs);
    }

    void run(int ms) {
        for (int t = 0; t < ms; t += kStepMs) {
            line->advance(kStepMs);
            for (int port = 1; port <= station->portCount(); ++port)
                if (const auto j = detectors[size_t(port - 1)].add(reading(port)))
                    found.append(*j);
        }
    }

    [[nodiscard]] PortReading reading(int port) const {
        const SimPort &p = station->port(port);
        PortReading r;
        r.timeMs = station->nowMs();
        r.tip = qRound(p.tip);
        r.setpoint = int(station->setting("ST" + QByteArray::number(port)).value_or(350));
        r.powerPct = p.power / 10.0;
        r.working = p.status == 0;
        r.tool = QString::number(p.tool);
        return r;
    }
};

// The detector's joint for a true one: same port, and the same depth to within the reading's
// rounding.
bool matches(const JointRecord &found, const SimJoint &truth) {
    return found.port == truth.port && found.recoveryMs &&
           qAbs(found.dipDepth - truth.depthK) <= 2 &&
           qAbs(*found.recoveryMs - truth.recoveryMs) <= 2 * kStepMs;
}

QString describe(const QList<JointRecord> &found) {
    QStringList out;
    for (const JointRecord &j : found)
        out.append(QStringLiteral("port %1 dip %2 K recovery %3 ms")
                       .arg(j.port)
                       .arg(j.dipDepth)
                       .arg(j.recoveryMs.value_or(-1)));
    return out.join(QStringLiteral("; "));
}
} // namespace

class TestSimJoints : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aJointCommandMakesTheJointTheDetectorMeasures_data();
    void aJointCommandMakesTheJointTheDetectorMeasures();
    void wearSlowsThatPortsRecoveriesOnly();
    void aBadJointCommandGetsAClearErrorAndChangesNothing_data();
    void aBadJointCommandGetsAClearErrorAndChangesNothing();
    void randomJointsComeOnEveryPortVariedAndRepeatable();
    void theSimulatorLogsEachJointWithItsTrueValues();
};

void TestSimJoints::aJointCommandMakesTheJointTheDetectorMeasures_data() {
    QTest::addColumn<int>("port");
    QTest::addColumn<int>("depth");
    QTest::addColumn<int>("recovery");
    QTest::newRow("shallow and quick") << 1 << 15 << 400;
    QTest::newRow("the demo's") << 2 << 50 << 1500;
    QTest::newRow("deep and quick") << 3 << 80 << 603;
    QTest::newRow("deep and slow") << 4 << 100 << 4000;
}

void TestSimJoints::aJointCommandMakesTheJointTheDetectorMeasures() {
    QFETCH(int, port);
    QFETCH(int, depth);
    QFETCH(int, recovery);
    Bench b;
    QSignalSpy made(b.line.get(), &SimLine::jointMade);
    QVERIFY(made.isValid());
    QCOMPARE(executeSimCommand(*b.line,
                               QStringLiteral("joint %1 %2 %3").arg(port).arg(depth).arg(recovery)),
             QStringLiteral("ok"));
    QCOMPARE(made.size(), 1);
    const auto truth = made.first().first().value<SimJoint>();
    QCOMPARE(truth.port, port);
    QCOMPARE(truth.depthK, depth);
    QCOMPARE(truth.recoveryMs, qint64(recovery));
    b.run(recovery + 5000);
    QVERIFY2(b.found.size() == 1 && matches(b.found.first(), truth), qPrintable(describe(b.found)));
    QVERIFY2(b.found.first().powerPeak > 60,
             qPrintable(QString::number(b.found.first().powerPeak)));
}

void TestSimJoints::wearSlowsThatPortsRecoveriesOnly() {
    Bench b;
    QSignalSpy made(b.line.get(), &SimLine::jointMade);
    QVERIFY(made.isValid());
    QCOMPARE(executeSimCommand(*b.line, QStringLiteral("wear 3 0.3")), QStringLiteral("ok"));
    QCOMPARE(executeSimCommand(*b.line, QStringLiteral("joint 3 40 1000")), QStringLiteral("ok"));
    QCOMPARE(executeSimCommand(*b.line, QStringLiteral("joint 1 40 1000")), QStringLiteral("ok"));
    b.run(6000);
    QCOMPARE(made.size(), 2);
    QCOMPARE(made.at(0).first().value<SimJoint>().recoveryMs, 1300);
    QCOMPARE(made.at(1).first().value<SimJoint>().recoveryMs, 1000);
    QCOMPARE(b.found.size(), 2);
    for (const JointRecord &j : std::as_const(b.found))
        QVERIFY2(matches(j, made.at(j.port == 3 ? 0 : 1).first().value<SimJoint>()),
                 qPrintable(describe(b.found)));
}

void TestSimJoints::aBadJointCommandGetsAClearErrorAndChangesNothing_data() {
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("reason");
    QTest::newRow("no such port, no depth") << "joint 9 x"
                                            << "port must be 1 to 4";
    QTest::newRow("no such port") << "joint 0 50 1000"
                                  << "port must be 1 to 4";
    QTest::newRow("depth not a number") << "joint 1 x 1000"
                                        << "whole numbers";
    QTest::newRow("recovery missing") << "joint 1 50"
                                      << "whole numbers";
    QTest::newRow("a word too many") << "joint 1 50 1000 2"
                                     << "whole numbers";
    QTest::newRow("too shallow to leave the band") << "joint 1 3 1000"
                                                   << "depth must be 6 to";
    QTest::newRow("recovery too long") << "joint 1 50 99999"
                                       << "recovery must be 100 to";
    QTest::newRow("a port in the stand") << "joint 2 50 1000"
                                         << "cannot make a joint now";
    QTest::newRow("wear on no such port") << "wear 9 0.3"
                                          << "port must be 1 to 4";
    QTest::newRow("wear beyond a share") << "wear 1 2"
                                         << "a share from 0 to 1";
    QTest::newRow("wear not a number") << "wear 1 x"
                                       << "a share from 0 to 1";
}

void TestSimJoints::aBadJointCommandGetsAClearErrorAndChangesNothing() {
    QFETCH(QString, command);
    QFETCH(QString, reason);
    Bench b;
    b.station->setStatus(2, 1);
    QSignalSpy made(b.line.get(), &SimLine::jointMade);
    QVERIFY(made.isValid());
    const QString reply = executeSimCommand(*b.line, command);
    QVERIFY2(reply.startsWith(QStringLiteral("error: ")) && reply.contains(reason),
             qPrintable(reply));
    b.run(5000);
    QVERIFY(made.isEmpty());
    QVERIFY2(b.found.isEmpty(), qPrintable(describe(b.found)));
    for (int port = 1; port <= b.station->portCount(); ++port) {
        QVERIFY(!b.station->port(port).joint);
        QCOMPARE(b.station->port(port).wear, 0.0);
    }
}

void TestSimJoints::randomJointsComeOnEveryPortVariedAndRepeatable() {
    QList<SimJoint> first;
    for (int round = 0; round < 2; ++round) {
        Bench b;
        QSignalSpy made(b.line.get(), &SimLine::jointMade);
        QVERIFY(made.isValid());
        b.line->setRandomJoints(10, 7);
        b.run(120'000);
        b.line->setRandomJoints(0, 7);
        b.run(10'000); // the last joints end
        QList<SimJoint> truth;
        for (const QList<QVariant> &signal : std::as_const(made))
            truth.append(signal.first().value<SimJoint>());
        // Port by port, in time order, each true joint is the detector's next one.
        QSet<int> ports, depths;
        QMap<int, qsizetype> next;
        QCOMPARE(b.found.size(), truth.size());
        for (const SimJoint &t : std::as_const(truth)) {
            ports.insert(t.port);
            depths.insert(t.depthK);
            qsizetype &k = next[t.port];
            while (k < b.found.size() && b.found.at(k).port != t.port)
                ++k;
            QVERIFY2(k < b.found.size() && matches(b.found.at(k), t),
                     qPrintable(QStringLiteral("port %1 dip %2 K recovery %3 ms, found: ")
                                    .arg(t.port)
                                    .arg(t.depthK)
                                    .arg(t.recoveryMs) +
                                describe(b.found)));
            ++k;
        }
        QCOMPARE(ports.size(), 4);
        QVERIFY2(truth.size() >= 4 * 8 && depths.size() > 10,
                 qPrintable(QString::number(truth.size())));
        if (round == 0) {
            first = truth;
            continue;
        }
        QCOMPARE(truth.size(), first.size()); // the same seed makes the same joints
        for (qsizetype i = 0; i < truth.size(); ++i) {
            QCOMPARE(truth.at(i).port, first.at(i).port);
            QCOMPARE(truth.at(i).depthK, first.at(i).depthK);
            QCOMPARE(truth.at(i).recoveryMs, first.at(i).recoveryMs);
        }
    }
}

void TestSimJoints::theSimulatorLogsEachJointWithItsTrueValues() {
    testing::SimProcess sim;
    QString error;
    const QString where = sim.start({"--model", "DME", "--tcp", "127.0.0.1:0"}, &error);
    QVERIFY2(!where.isEmpty(), qPrintable(error));
    QCOMPARE(sim.command(QStringLiteral("joint 9 x")),
             QStringLiteral("error: port must be 1 to 4"));
    // The ports heat up first; until then the command says why it makes no joint. (A loop, not
    // QTRY: the command must be sent once more only while it failed.)
    qint64 before = 0;
    QString reply;
    const QDeadlineTimer heated(15000);
    while (reply != QLatin1String("ok") && !heated.hasExpired()) {
        QTest::qWait(100);
        before = QDateTime::currentMSecsSinceEpoch();
        reply = sim.command(QStringLiteral("joint 3 40 800"));
        QVERIFY2(reply == QLatin1String("ok") || reply.startsWith(QStringLiteral("error: port 3 ")),
                 qPrintable(reply));
    }
    QCOMPARE(reply, QStringLiteral("ok"));
    const qint64 after = QDateTime::currentMSecsSinceEpoch();
    static const QRegularExpression logged(
        QStringLiteral("^tipscope-sim: joint port=(\\d+) start_ms=(\\d+) depth_k=(\\d+) "
                       "recovery_ms=(\\d+) drop_ms=(\\d+) form=exponential overshoot_k=0\\.0$"),
        QRegularExpression::MultilineOption);
    QRegularExpressionMatch m;
    QString log;
    QTRY_VERIFY_WITH_TIMEOUT(
        (m = logged.match(log += QString::fromLocal8Bit(sim.process().readAllStandardError())))
            .hasMatch(),
        5000);
    QCOMPARE(m.captured(1), QStringLiteral("3"));
    QCOMPARE(m.captured(3), QStringLiteral("40"));
    QCOMPARE(m.captured(4), QStringLiteral("800"));
    // It left the band a fraction of the drop after the command: within the command's time.
    const qint64 start = m.captured(2).toLongLong();
    QVERIFY2(start >= before && start <= after + 200,
             qPrintable(QStringLiteral("%1 not in [%2, %3]").arg(start).arg(before).arg(after)));
    QCOMPARE(m.captured(5), QStringLiteral("200")); // a quarter of the recovery

    // Once over, the same joint again: nobody read its tip, so no read depth either.
    const QRegularExpression ended(
        QStringLiteral("^tipscope-sim: joint-end port=3 start_ms=%1 reads=0 read_depth_k=0\\.00$")
            .arg(start),
        QRegularExpression::MultilineOption);
    QTRY_VERIFY_WITH_TIMEOUT(
        ended.match(log += QString::fromLocal8Bit(sim.process().readAllStandardError())).hasMatch(),
        5000);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSimJoints)

} // namespace tst_simjoints
#include "tst_simjoints.moc"
