// A reading the station refuses costs only itself, in the programs too: tipscope-cli monitor and
// tipscope-agent, each on a simulated DME that answers one reading with NAK 00004 from the start
// (as a station without that reading would), still read the tips, find the joint made on port 1
// and keep it in their journal with its figures, and journal the refusal once. The simulator is
// paced at 19200 baud like a station's line: unpaced, a program that fills its wire would spin
// both processes at full speed and starve the tests running beside this one.
#include "../mqtt/mqtttesting.h"
#include "journaledfrontend.h"
#include "mosquittobroker.h"
#include "ptyfixtures.h"
#include "testmain.h"

#include <QRegularExpression>
#include <QTest>

namespace tst_refusedreadings {

using namespace tipscope;
using namespace tipscope::testing;
using journal::JournalEvent;

namespace {

// What the journal says about reading `command`.
QStringList refusalsIn(const JournaledFrontEnd &frontEnd, const QByteArray &command) {
    QStringList said;
    for (const auto &e : frontEnd.events(JournalEvent::Kind::Communication))
        if (e.record.text.contains(QString::fromLatin1(command)))
            said.append(e.record.text);
    return said;
}

} // namespace

class TestRefusedReadings : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { TIPSCOPE_START_BROKER(m_broker); }
    void aRefusedReadingCostsOnlyItself_data();
    void aRefusedReadingCostsOnlyItself();

private:
    MosquittoBroker m_broker;
};

void TestRefusedReadings::aRefusedReadingCostsOnlyItself_data() {
    QTest::addColumn<bool>("agent");
    QTest::addColumn<QByteArray>("command");
    QTest::newRow("monitor, transformer temperature") << false << QByteArray("TT0");
    QTest::newRow("monitor, port status") << false << QByteArray("PS1");
    QTest::newRow("agent, transformer temperature") << true << QByteArray("TT0");
    QTest::newRow("agent, transistor temperature") << true << QByteArray("QT1");
}

void TestRefusedReadings::aRefusedReadingCostsOnlyItself() {
    QFETCH(bool, agent);
    QFETCH(QByteArray, command);
    SimProcess sim;
    QString error;
    const QString line =
        sim.start({QStringLiteral("--model"), QStringLiteral("DME"), QStringLiteral("--tcp"),
                   QStringLiteral("127.0.0.1:0"), QStringLiteral("--pace"), QStringLiteral("19200"),
                   QStringLiteral("--nak"), QStringLiteral("4"), QStringLiteral("--nak-for"),
                   QString::fromLatin1(command)},
                  &error);
    QVERIFY2(!line.isEmpty(), qPrintable(error));

    JournaledFrontEnd frontEnd(agent ? JournaledFrontEnd::Kind::Agent
                                     : JournaledFrontEnd::Kind::Monitor);
    QVERIFY2(frontEnd.start(line, m_broker.port(), &error), qPrintable(error));

    // A joint on port 1 once the port is at work at its temperature and the program saw it
    // settle (no joint without a baseline: the first one, made as soon as the port is hot, may
    // come too early), so asked for again, further apart than a settling takes, until the
    // journal holds one.
    QVERIFY(QTest::qWaitFor(
        [&] {
            if (sim.command(QStringLiteral("joint 1 40 800")) == QLatin1String("ok"))
                return true;
            QTest::qWait(300);
            return false;
        },
        20000));
    QVERIFY2(QTest::qWaitFor(
                 [&] {
                     if (QTest::qWaitFor([&] { return !frontEnd.joints().isEmpty(); }, 6000))
                         return true;
                     (void)sim.command(QStringLiteral("joint 1 40 800"));
                     return false;
                 },
                 30000),
             qPrintable(frontEnd.log()));
    const QList<journal::StoredJoint> joints = frontEnd.joints();
    const model::JointRecord &j = joints.first().record;
    QCOMPARE(j.port, 1);
    // Read on a 19200-baud line, a 200 ms drop is seen by a reading every 100-160 ms: the
    // lowest reading may miss the bottom by a few kelvin (docs/joints.md, the oracle's error);
    // readings further apart (a loaded machine) miss more, and the joint says by how much.
    QVERIFY2(qAbs(j.dipDepth - 40) <= qMax(6.0, j.dipUncertaintyK),
             qPrintable(QStringLiteral("%1 ± %2 K").arg(j.dipDepth).arg(j.dipUncertaintyK)));
    QVERIFY(j.recoveryMs);
    QVERIFY2(qAbs(*j.recoveryMs - 800) <= 250, qPrintable(QString::number(*j.recoveryMs)));
    QVERIFY(j.verdict != model::JointVerdict::Incomplete);
    // The refusal is journaled once, with the station's reason.
    QVERIFY(QTest::qWaitFor([&] { return !refusalsIn(frontEnd, command).isEmpty(); }, 10000));
    const QStringList refusals = refusalsIn(frontEnd, command);
    QVERIFY2(refusals.size() == 1, qPrintable(refusals.join(QLatin1Char('\n'))));
    QVERIFY2(refusals.first().contains(QStringLiteral("00004")) ||
                 refusals.first().contains(QStringLiteral("NAK")),
             qPrintable(refusals.first()));

    const int exitStatus = frontEnd.stop();
    QVERIFY2(exitStatus == 0, qPrintable(QString::number(exitStatus) + frontEnd.log()));
    if (agent)
        return;
    const QString out = frontEnd.output();
    // The tips were printed all along: every cycle after the first reads "P1 <tip>/<setpoint>".
    static const QRegularExpression tipShown(QStringLiteral("P1 \\d+/\\d+ °C"));
    const QStringList cycles = out.split(QLatin1Char('\n')).filter(QStringLiteral(" P1 "));
    QVERIFY2(cycles.size() >= 5, qPrintable(out));
    QVERIFY2(cycles.filter(tipShown).size() >= cycles.size() - 2, qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("joint P1 ")), qPrintable(out));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestRefusedReadings)

} // namespace tst_refusedreadings
#include "tst_refusedreadings.moc"
