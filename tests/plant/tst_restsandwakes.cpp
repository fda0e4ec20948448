// A tool put to sleep and picked up again is no joint, and each change is an event stamped when
// the tip shows it, in the programs too: tipscope-cli monitor and tipscope-agent, each on a
// simulated DME paced like a station's line. Port 1 starts asleep (its tip heats to its sleep
// temperature under the sleep status, which is no wake either), is woken, climbs to its setpoint
// and is put to sleep again. The journal holds no joint and two status events, each within half
// a second of the command that changed the port: the simulated tip moves at once, so that is
// when the samples show it.
#include "../mqtt/mqtttesting.h"
#include "journaledfrontend.h"
#include "mosquittobroker.h"
#include "ptyfixtures.h"

#include <QDateTime>
#include <QTest>

using namespace tipscope;
using namespace tipscope::testing;
using journal::JournalEvent;

namespace {

constexpr qint64 kStampedWithinMs = 500;

QList<JournalEvent> statusEventsOfPort1(const JournaledFrontEnd &frontEnd) {
    QList<JournalEvent> out;
    for (const journal::StoredEvent &e : frontEnd.events(JournalEvent::Kind::Status))
        if (e.record.port == 1)
            out.append(e.record);
    return out;
}

// The first status event at or after `fromMs` whose text ends in `mode`.
std::optional<JournalEvent> changeTo(const QList<JournalEvent> &events, const QString &mode,
                                     qint64 fromMs) {
    for (const JournalEvent &e : events)
        if (e.timeMs >= fromMs && e.text.endsWith(mode))
            return e;
    return std::nullopt;
}

QString listed(const QList<JournalEvent> &events) {
    QStringList lines;
    for (const JournalEvent &e : events)
        lines << QStringLiteral("%1 %2").arg(e.timeMs).arg(e.text);
    return lines.join(QLatin1Char('\n'));
}

} // namespace

class TestRestsAndWakes : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { TIPSCOPE_START_BROKER(m_broker); }
    void aSleepAndAWakeAreEventsOnTimeAndNoJoints_data();
    void aSleepAndAWakeAreEventsOnTimeAndNoJoints();

private:
    MosquittoBroker m_broker;
};

void TestRestsAndWakes::aSleepAndAWakeAreEventsOnTimeAndNoJoints_data() {
    QTest::addColumn<bool>("agent");
    QTest::newRow("monitor") << false;
    QTest::newRow("agent") << true;
}

void TestRestsAndWakes::aSleepAndAWakeAreEventsOnTimeAndNoJoints() {
    QFETCH(bool, agent);
    SimProcess sim;
    QString error;
    const QString line = sim.start({QStringLiteral("--model"), QStringLiteral("DME"),
                                    QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0"),
                                    QStringLiteral("--pace"), QStringLiteral("19200")},
                                   &error);
    QVERIFY2(!line.isEmpty(), qPrintable(error));
    QCOMPARE(sim.command(QStringLiteral("status 1 2")), QStringLiteral("ok"));
    JournaledFrontEnd frontEnd(agent ? JournaledFrontEnd::Kind::Agent
                                     : JournaledFrontEnd::Kind::Monitor);
    QVERIFY2(frontEnd.start(line, m_broker.port(), &error), qPrintable(error));

    // Asleep, its tip heats to 150 °C (about 3 s from cold); then it wakes and climbs to 350 °C
    // (about 3 s), and sleeps again.
    QTest::qWait(6000);
    const qint64 wokenMs = QDateTime::currentMSecsSinceEpoch();
    QCOMPARE(sim.command(QStringLiteral("status 1 0")), QStringLiteral("ok"));
    QTest::qWait(8000);
    const qint64 sleptMs = QDateTime::currentMSecsSinceEpoch();
    QCOMPARE(sim.command(QStringLiteral("status 1 2")), QStringLiteral("ok"));
    QVERIFY2(QTest::qWaitFor(
                 [&] {
                     return changeTo(statusEventsOfPort1(frontEnd), QStringLiteral("Sleep"),
                                     sleptMs)
                         .has_value();
                 },
                 10000),
             qPrintable(listed(statusEventsOfPort1(frontEnd)) + frontEnd.log()));
    QTest::qWait(2000); // the cooling after it: no joint either

    const int exitStatus = frontEnd.stop();
    QVERIFY2(exitStatus == 0, qPrintable(QString::number(exitStatus) + frontEnd.log()));
    const QList<JournalEvent> events = statusEventsOfPort1(frontEnd);
    const auto working = changeTo(events, QStringLiteral("Working"), wokenMs);
    const auto asleep = changeTo(events, QStringLiteral("Sleep"), sleptMs);
    QVERIFY2(working && asleep, qPrintable(listed(events)));
    const QString stamps = QStringLiteral("the wake stamped %1 ms after it, the sleep %2 ms after")
                               .arg(working->timeMs - wokenMs)
                               .arg(asleep->timeMs - sleptMs);
    qInfo().noquote() << stamps;
    QVERIFY2(working->timeMs - wokenMs <= kStampedWithinMs, qPrintable(stamps));
    QVERIFY2(asleep->timeMs - sleptMs <= kStampedWithinMs, qPrintable(stamps));
    const QList<journal::StoredJoint> joints = frontEnd.joints();
    QVERIFY2(joints.isEmpty(),
             qPrintable(QStringLiteral("%1 joints, the first at %2 ms after the wake")
                            .arg(joints.size())
                            .arg(joints.isEmpty() ? 0 : joints.first().record.startMs - wokenMs)));
}

QTEST_GUILESS_MAIN(TestRestsAndWakes)
#include "tst_restsandwakes.moc"
