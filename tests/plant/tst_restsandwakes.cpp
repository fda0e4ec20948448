// A tool put to sleep and picked up again, or taken out and put back, is no joint, and each
// change is an event stamped when the tip shows it, in the programs too: tipscope-cli monitor and
// tipscope-agent, each on a simulated DME paced like a station's line. The journal holds no joint
// and the events, each within half a second of the command that changed the port: the simulated
// tip moves at once, so that is when the samples show it.
#include "../mqtt/mqtttesting.h"
#include "journaledfrontend.h"
#include "mosquittobroker.h"
#include "ptyfixtures.h"
#include "testmain.h"

#include <QDateTime>
#include <QTest>

namespace tst_restsandwakes {

using namespace tipscope;
using namespace tipscope::testing;
using journal::JournalEvent;

namespace {

constexpr qint64 kStampedWithinMs = 500;

QList<JournalEvent> eventsOfPort1(const JournaledFrontEnd &frontEnd,
                                  JournalEvent::Kind kind = JournalEvent::Kind::Status) {
    QList<JournalEvent> out;
    for (const journal::StoredEvent &e : frontEnd.events(kind))
        if (e.record.port == 1)
            out.append(e.record);
    return out;
}

QList<JournalEvent> statusEventsOfPort1(const JournaledFrontEnd &frontEnd) {
    return eventsOfPort1(frontEnd);
}

// The first event at or after `fromMs` whose text ends in `text`.
std::optional<JournalEvent> changeTo(const QList<JournalEvent> &events, const QString &text,
                                     qint64 fromMs) {
    for (const JournalEvent &e : events)
        if (e.timeMs >= fromMs && e.text.endsWith(text))
            return e;
    return std::nullopt;
}

// The first event at or after `fromMs` whose text starts with `text`.
std::optional<JournalEvent> changeFrom(const QList<JournalEvent> &events, const QString &text,
                                       qint64 fromMs) {
    for (const JournalEvent &e : events)
        if (e.timeMs >= fromMs && e.text.startsWith(text))
            return e;
    return std::nullopt;
}

QString startSim(SimProcess &sim, QString *error) {
    return sim.start({QStringLiteral("--model"), QStringLiteral("DME"), QStringLiteral("--tcp"),
                      QStringLiteral("127.0.0.1:0"), QStringLiteral("--pace"),
                      QStringLiteral("19200")},
                     error);
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
    void aToolTakenOutAndPutBackIsOnTimeAndNoJoint_data();
    void aToolTakenOutAndPutBackIsOnTimeAndNoJoint();

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
    const QString line = startSim(sim, &error);
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

void TestRestsAndWakes::aToolTakenOutAndPutBackIsOnTimeAndNoJoint_data() {
    aSleepAndAWakeAreEventsOnTimeAndNoJoints_data();
}

// The tool is taken out of a working port: the station reports no tool and a port error, its
// heater stops and the tip cools; then a tool goes back in and the tip climbs. Each change is an
// event within half a second of the command (the simulated tip moves at once), and neither the
// cooling nor the climb is a joint.
void TestRestsAndWakes::aToolTakenOutAndPutBackIsOnTimeAndNoJoint() {
    QFETCH(bool, agent);
    SimProcess sim;
    QString error;
    const QString line = startSim(sim, &error);
    QVERIFY2(!line.isEmpty(), qPrintable(error));
    JournaledFrontEnd frontEnd(agent ? JournaledFrontEnd::Kind::Agent
                                     : JournaledFrontEnd::Kind::Monitor);
    QVERIFY2(frontEnd.start(line, m_broker.port(), &error), qPrintable(error));
    const QString noTool = QStringLiteral("No tool");

    QTest::qWait(6000); // heated to its setpoint and settled
    const qint64 outMs = QDateTime::currentMSecsSinceEpoch();
    QCOMPARE(sim.command(QStringLiteral("tool 1 0")), QStringLiteral("ok"));
    QTest::qWait(3000); // the tip cools
    const qint64 backMs = QDateTime::currentMSecsSinceEpoch();
    QCOMPARE(sim.command(QStringLiteral("tool 1 1")), QStringLiteral("ok"));
    const auto toolEvents = [&] { return eventsOfPort1(frontEnd, JournalEvent::Kind::ToolChange); };
    QVERIFY2(QTest::qWaitFor([&] { return changeFrom(toolEvents(), noTool, backMs).has_value(); },
                             10000),
             qPrintable(listed(toolEvents()) + QStringLiteral(" status: ") +
                        listed(statusEventsOfPort1(frontEnd)) + QStringLiteral(" all: ") +
                        [&] {
                            QString o;
                            for (int k = 0; k <= int(JournalEvent::Kind::Journal); ++k)
                                for (const auto &e : frontEnd.events(JournalEvent::Kind(k)))
                                    o += QStringLiteral("%1 p%2 %3; ")
                                             .arg(e.record.timeMs)
                                             .arg(e.record.port.value_or(-1))
                                             .arg(e.record.text);
                            return o;
                        }() +
                        QStringLiteral(" out %1 ").arg(outMs) +
                        QStringLiteral(" back %1 ").arg(backMs) + frontEnd.log()));
    QTest::qWait(3000); // the climb back to the setpoint: no joint either

    const int exitStatus = frontEnd.stop();
    QVERIFY2(exitStatus == 0, qPrintable(QString::number(exitStatus) + frontEnd.log()));
    const QList<JournalEvent> tools = toolEvents();
    const QList<JournalEvent> errors = eventsOfPort1(frontEnd, JournalEvent::Kind::PortError);
    const auto out = changeTo(tools, noTool, outMs);
    const auto back = changeFrom(tools, noTool, backMs);
    const auto fault = changeTo(errors, noTool, outMs);
    const auto cleared = changeTo(errors, QStringLiteral("error cleared"), backMs);
    QVERIFY2(out && back && fault && cleared, qPrintable(listed(tools) + '\n' + listed(errors)));
    const QString stamps =
        QStringLiteral("taken out: tool %1 ms, error %2 ms after it; put back: tool %3 ms, "
                       "error cleared %4 ms after it")
            .arg(out->timeMs - outMs)
            .arg(fault->timeMs - outMs)
            .arg(back->timeMs - backMs)
            .arg(cleared->timeMs - backMs);
    qInfo().noquote() << stamps;
    for (const qint64 late : {out->timeMs - outMs, fault->timeMs - outMs, back->timeMs - backMs,
                              cleared->timeMs - backMs})
        QVERIFY2(late <= kStampedWithinMs, qPrintable(stamps));
    const QList<journal::StoredJoint> joints = frontEnd.joints();
    QVERIFY2(joints.isEmpty(),
             qPrintable(QStringLiteral("%1 joints, the first at %2 ms after the tool was taken out")
                            .arg(joints.size())
                            .arg(joints.isEmpty() ? 0 : joints.first().record.startMs - outMs)));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestRestsAndWakes)

} // namespace tst_restsandwakes
#include "tst_restsandwakes.moc"
