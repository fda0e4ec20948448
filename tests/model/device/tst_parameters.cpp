// Every parameter of a DME, a DDR and an SFR reads, validates, writes and verifies against the
// simulator through the real link; refused values never reach the wire.
#include "model/simfixture.h"
#include "testmain.h"

#include "model/events/eventlog.h"

namespace tst_parameters {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::protocol;
using namespace tipscope::testing;

namespace {

// A value different from the current one that the parameter accepts now.
std::optional<qint64> otherValidValue(const Parameter &p) {
    const ResolvedCommand &c = p.spec();
    const qint64 current = p.number().value_or(-99999);
    QList<qint64> candidates;
    if (c.spec->kind == ValueKind::Enum)
        candidates = QList<qint64>(c.values.keyBegin(), c.values.keyEnd());
    else
        candidates = {p.minimum() + c.spec->step, p.maximum() - c.spec->step, p.minimum(),
                      p.maximum()};
    for (int special : c.spec->special.keys())
        candidates.append(special);
    for (qint64 v : candidates)
        if (v != current && p.validate(v).isEmpty())
            return v;
    return std::nullopt;
}

bool writeAndWait(Parameter &p, qint64 value, QString *why) {
    *why = p.setEdit(value);
    if (!why->isEmpty())
        return false;
    QSignalSpy done(&p, &Parameter::writeFinished);
    p.apply();
    if (!done.wait(10000)) {
        *why = QStringLiteral("no writeFinished");
        return false;
    }
    *why = done.first().at(1).toString();
    return done.first().at(0).toBool();
}

} // namespace

class TestParameters : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aProvedWriteAndAToolChangeAreEventsForTheJournal();
    void everyParameterReadsWritesAndVerifies_data();
    void everyParameterReadsWritesAndVerifies();
    void refusedValuesNeverReachTheWire();
    void selectedTemperatureFollowsTheStationsLimits();
    void fahrenheitIsShownAndTypedButCelsiusIsSent();
    void aNakLeavesTheParameterFailedWithTheReasonAndKeepsTheEdit();
    void aReadBackThatDiffersIsReadOnceMoreBeforeTheWriteFails_data();
    void aReadBackThatDiffersIsReadOnceMoreBeforeTheWriteFails();
    void eachWriteEndsOnceWithItsOwnId();
    void monitorOnlyBlocksEveryWrite();
    void dangerousActionsNeedConfirmation();
    void saveToMemoryMarksSelectedTemperaturesSaved();
    void portStatusDecodesFlagsAndRobotControlsWork();
    void injectedErrorsAndAlarmsReachTheEventLog();
    void feederCommandsAndCountersWork();
};

void TestParameters::everyParameterReadsWritesAndVerifies_data() {
    QTest::addColumn<QString>("family");
    QTest::newRow("DME") << "DME";
    QTest::newRow("DDR") << "DDR";
    QTest::newRow("SFR") << "SFR";
}

void TestParameters::everyParameterReadsWritesAndVerifies() {
    QFETCH(QString, family);
    SimFixture f(singleDevice(family));
    std::unique_ptr<DeviceModel> device;
    if (family == QLatin1String("SFR"))
        device = f.feeder();
    else
        device = f.station();
    device->refreshAll();
    f.settle();
    int readable = 0, written = 0;
    for (Parameter *p : device->parameters()) {
        if (p->isReadable()) {
            ++readable;
            QVERIFY2(p->value().has_value(), p->code().constData());
            QCOMPARE(p->state(), Parameter::State::InSync);
        }
        if (!p->isWritable() || p->meta().kind == ValueKind::Flags)
            continue;
        const auto v = otherValidValue(*p);
        QVERIFY2(v, p->code().constData());
        QString why;
        QVERIFY2(writeAndWait(*p, *v, &why),
                 qPrintable(QString::fromLatin1(p->code()) + ": " + why));
        QCOMPARE(p->state(), Parameter::State::InSync);
        QCOMPARE(p->number().value(), *v);
        QCOMPARE(f.simLine->devices().first()->setting(p->code()).value(), *v);
        ++written;
    }
    QVERIFY(readable > 10);
    QVERIFY(written > (family == QLatin1String("SFR") ? 3 : 20));
}

void TestParameters::refusedValuesNeverReachTheWire() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    const qint64 writesBefore = f.simLine->stats().writeRequests;
    int refused = 0;
    for (Parameter *p : st->parameters()) {
        if (!p->isWritable() ||
            (p->meta().kind != ValueKind::Number && p->meta().kind != ValueKind::Delay))
            continue;
        for (qint64 bad : {p->maximum() + p->meta().step, p->minimum() - 1}) {
            if (p->meta().special.contains(int(bad)))
                continue;
            const QString why = p->setEdit(bad);
            QVERIFY2(!why.isEmpty(), qPrintable(QString::fromLatin1(p->code()) + " accepted " +
                                                QString::number(bad)));
            QVERIFY2(why.contains(QStringLiteral("allowed is")), qPrintable(why));
            ++refused;
        }
        p->apply(); // nothing pending: must not send
    }
    QVERIFY(refused > 40);
    QCOMPARE(st->parameter("ST1")->setEditText(QStringLiteral("hot")).isEmpty(), false);
    QCOMPARE(st->parameter("ST1")->setEditText(QStringLiteral("352")).isEmpty(), false);
    QCoreApplication::processEvents();
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, writesBefore);
}

void TestParameters::selectedTemperatureFollowsTheStationsLimits() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    Parameter *mat = st->parameter("MAT");
    Parameter *st1 = st->parameter("ST1");
    QCOMPARE(st1->maximum(), 500);
    QString why;
    QVERIFY2(writeAndWait(*mat, 400, &why), qPrintable(why));
    QCOMPARE(st1->maximum(), 400);
    QVERIFY(st1->setEdit(420).contains(QStringLiteral("400")));
    QVERIFY(st1->setEdit(400).isEmpty());
    QVERIFY(st->parameter("MIT")->setEdit(405).contains(QStringLiteral("allowed")));
}

void TestParameters::fahrenheitIsShownAndTypedButCelsiusIsSent() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    st->setTemperatureUnit(TemperatureUnit::Fahrenheit);
    Parameter *st1 = st->parameter("ST1");
    QCOMPARE(st1->displayText(), QStringLiteral("662 °F"));
    QVERIFY(st1->setEditText(QStringLiteral("660")).contains(QStringLiteral("steps of 9 °F")));
    QVERIFY(st1->setEditText(QStringLiteral("680 °F")).isEmpty());
    QCOMPARE(st1->edit().value(), 360);
    Parameter *adjust = st->parameter("A12");
    QVERIFY(adjust->setEditText(QStringLiteral("-18")).isEmpty());
    QCOMPARE(adjust->edit().value(), -10); // a difference converts without the 32
    QCOMPARE(st->parameter("PP1")->displayText().endsWith(QStringLiteral("%")), true);
}

void TestParameters::aNakLeavesTheParameterFailedWithTheReasonAndKeepsTheEdit() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    sim::SimFaults faults;
    faults.nakCode = 3;
    f.simLine->setFaults(faults);
    Parameter *p = st->parameter("ST2");
    QString why;
    QVERIFY(!writeAndWait(*p, 300, &why));
    QVERIFY2(why.contains(QStringLiteral("Out of range")), qPrintable(why));
    QCOMPARE(p->state(), Parameter::State::Failed);
    QCOMPARE(p->edit().value(), 300);
    f.simLine->setFaults({});
    QVERIFY(writeAndWait(*p, 300, &why));
}

void TestParameters::aReadBackThatDiffersIsReadOnceMoreBeforeTheWriteFails_data() {
    QTest::addColumn<int>("staleAnswers");
    QTest::addColumn<bool>("verified");
    QTest::newRow("one stale answer") << 1 << true;
    QTest::newRow("the device keeps the old value") << 1000 << false;
}

// Frames carry no sequence number: a read-back may get the late answer of an earlier read, from
// before the write. The simulator answers the read-backs with the old value, as such a late
// answer would.
void TestParameters::aReadBackThatDiffersIsReadOnceMoreBeforeTheWriteFails() {
    QFETCH(int, staleAnswers);
    QFETCH(bool, verified);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    sim::SimStation *device = f.simLine->station();
    const qint64 before = device->setting("ST2").value();
    bool written = false;
    int readsAfterWrite = 0;
    connect(f.simLine.get(), &sim::SimLine::requestReceived, this, [&](const Frame &request) {
        if (request.command != "ST2")
            return;
        written = written || request.header == Header::Write;
        if (!written || request.header != Header::Read)
            return;
        if (++readsAfterWrite > staleAnswers)
            return;
        // Answered with the old value, then given back the new one from the event loop: the
        // answer may be taken before then (the line hands its bytes over at once), so the value
        // is looked at once that has happened. Gone with the line, should the test end first.
        const qint64 now = device->setting("ST2").value();
        device->setSetting("ST2", before);
        QTimer::singleShot(0, f.simLine.get(), [device, now] { device->setSetting("ST2", now); });
    });
    Parameter *p = st->parameter("ST2");
    QString why;
    QCOMPARE(writeAndWait(*p, 300, &why), verified);
    QCOMPARE(readsAfterWrite, 2);
    QTRY_COMPARE(device->setting("ST2").value(), 300);
    if (verified) {
        QCOMPARE(p->state(), Parameter::State::InSync);
        QCOMPARE(p->number().value(), 300);
    } else {
        QVERIFY2(why.contains(QStringLiteral("the device reports")), qPrintable(why));
        QCOMPARE(p->number().value(), before);
    }
}

// A caller tells its writes' outcomes apart by id: a finish can never be taken for another
// write's, and apply() says at once when it started nothing.
void TestParameters::eachWriteEndsOnceWithItsOwnId() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    Parameter *p = st->parameter("ST3");
    QSignalSpy done(p, &Parameter::writeFinished);
    QVERIFY(done.isValid());
    QCOMPARE(p->apply(), quint64(0)); // nothing pending
    QVERIFY(p->setEdit(p->number().value()).isEmpty());
    QCOMPARE(p->apply(), quint64(0)); // the device holds it already

    QVERIFY(p->setEdit(300).isEmpty());
    const quint64 first = p->apply();
    QVERIFY(first != 0);
    QVERIFY(p->setEdit(310).isEmpty()); // edited while the write runs
    QCOMPARE(p->apply(), quint64(0));   // one write of a parameter at a time
    QVERIFY(done.wait(10000));
    QCOMPARE(done.count(), 1);
    QCOMPARE(done.first().at(0).toBool(), true);
    QCOMPARE(done.first().at(2).value<quint64>(), first);

    QVERIFY(p->setEdit(320).isEmpty());
    st->setWritesBlocked(true); // refused inside apply(): still told after apply() returned
    const quint64 refused = p->apply();
    QVERIFY(refused != 0 && refused != first);
    QCOMPARE(done.count(), 1);
    QTRY_COMPARE(done.count(), 2);
    QCOMPARE(done.last().at(0).toBool(), false);
    QCOMPARE(done.last().at(2).value<quint64>(), refused);
    QTest::qWait(100);
    f.settle();
    QCOMPARE(done.count(), 2);
}

void TestParameters::monitorOnlyBlocksEveryWrite() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    st->setWritesBlocked(true);
    QVERIFY(st->parameter("ST1")->setEdit(300).contains(QStringLiteral("monitor-only")));
    QVERIFY(st->saveToMemory().contains(QStringLiteral("monitor-only")));
    QVERIFY(st->port(1)->setMode(1).contains(QStringLiteral("monitor-only")));
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
}

void TestParameters::dangerousActionsNeedConfirmation() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    QVERIFY(st->factoryReset(Confirmation::None).contains(QStringLiteral("factory value")));
    QVERIFY(!st->restart(Confirmation::None).isEmpty());
    QVERIFY(!st->setAddress(5, Confirmation::None).isEmpty());
    QVERIFY(!st->ignoreFuseError(Confirmation::Confirmed).isEmpty()); // a DME has no fuse command
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
    QSignalSpy done(st->action("RSP"), &Action::finished);
    QVERIFY(st->factoryReset(Confirmation::Confirmed).isEmpty());
    QVERIFY(done.wait());
    QVERIFY(done.first().at(0).toBool());
}

void TestParameters::saveToMemoryMarksSelectedTemperaturesSaved() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    Parameter *st1 = st->parameter("ST1");
    QString why;
    QVERIFY(writeAndWait(*st1, 300, &why));
    QVERIFY(!st1->isSavedToMemory());
    QSignalSpy done(st->action("NVS"), &Action::finished);
    QVERIFY(st->saveToMemory().isEmpty());
    QVERIFY(done.wait());
    QVERIFY(st1->isSavedToMemory());
    QVERIFY(st->parameter("MAT")->isSavedToMemory()); // not volatile
    QVERIFY(st->parameter("ST2")->isSavedToMemory()); // TipScope did not change it
}

void TestParameters::portStatusDecodesFlagsAndRobotControlsWork() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    PortModel *port = st->port(2);
    QSignalSpy written(port->parameter(Role::Status), &Parameter::writeFinished);
    QVERIFY(port->setMode(10).isEmpty());
    QVERIFY(written.wait());
    QVERIFY2(written.first().at(0).toBool(), qPrintable(written.first().at(1).toString()));
    QVERIFY(port->status()->cooling);
    QCOMPARE(port->status()->text(), QStringLiteral("Working, Cooling"));
    QCOMPARE(PortStatus::fromNumber(1102).text(), QStringLiteral("Sleep, Suction, Motor forward"));
    QVERIFY(!port->setMode(2).isEmpty()); // sleep is reached by the delay only
    QCOMPARE(port->toolOrder().first(), f.simLine->station()->port(2).tool);
    QCOMPARE(port->toolSettings(port->toolOrder().first()).size(), 4);
    QCOMPARE(port->counters().size(), 7);
}

void TestParameters::aProvedWriteAndAToolChangeAreEventsForTheJournal() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    EventLog log;
    st->setEventLog(&log);
    st->refreshAll();
    f.settle();
    QString why;
    QVERIFY2(writeAndWait(*st->parameter("ST1"), 360, &why), qPrintable(why));
    const QList<Event> written = log.events();
    const auto write = std::find_if(written.cbegin(), written.cend(),
                                    [](const Event &e) { return e.kind == Event::Kind::Write; });
    QVERIFY(write != written.cend());
    QCOMPARE(write->port, 1);
    QCOMPARE(write->details.value(QStringLiteral("code")).toString(), QStringLiteral("ST1"));
    QCOMPARE(write->details.value(QStringLiteral("value")).toString(), QStringLiteral("360 °C"));
    QCOMPARE(write->details.value(QStringLiteral("readBack")).toString(),
             QStringLiteral("confirmed"));

    // The tool pulled from port 2: a tool change, not a status change.
    const QString before = st->port(2)->toolName();
    f.simLine->station()->setTool(2, 0);
    st->port(2)->parameter(Role::ConnectedTool)->refresh();
    f.settle();
    const QList<Event> events = log.events();
    const auto change = std::find_if(events.cbegin(), events.cend(), [](const Event &e) {
        return e.kind == Event::Kind::ToolChange;
    });
    QVERIFY(change != events.cend());
    QCOMPARE(change->port, 2);
    QVERIFY2(change->text.startsWith(before + QStringLiteral(" → ")), qPrintable(change->text));
}

void TestParameters::injectedErrorsAndAlarmsReachTheEventLog() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    EventLog log;
    st->setEventLog(&log);
    st->refreshAll();
    f.settle();
    f.simLine->station()->setPortError(3, 1);
    f.simLine->station()->latchAlarm(1, 10);
    f.simLine->station()->setStationError(7);
    st->port(3)->parameter(Role::Error)->refresh();
    st->port(1)->parameter(Role::Alarm)->refresh();
    st->parameter("SER")->refresh();
    f.settle();
    QStringList texts;
    for (const Event &e : log.events())
        texts.append(e.source + QStringLiteral(": ") + e.text);
    QVERIFY2(texts.join('\n').contains(QStringLiteral("port 3: Short circuit")),
             qPrintable(texts.join('\n')));
    QVERIFY(texts.join('\n').contains(QStringLiteral("Low temperature alarm")));
    QVERIFY(texts.join('\n').contains(QStringLiteral("Warning: transformer overload")));
    QCOMPARE(st->port(3)->errorText(), QStringLiteral("Short circuit"));
}

void TestParameters::feederCommandsAndCountersWork() {
    SimFixture f(singleDevice(QStringLiteral("SFR")));
    auto fd = f.feeder();
    fd->refreshAll();
    f.settle();
    QCOMPARE(fd->counters().size(), 6);
    QSignalSpy started(fd->action("SFD"), &Action::finished);
    QVERIFY(fd->startFeeding(true).isEmpty());
    QVERIFY(started.wait());
    QVERIFY(f.simLine->feeder()->isFeeding());
    QVERIFY(!fd->resetPartialCounter("CTP", Confirmation::None).isEmpty());
    QSignalSpy reset(fd->action("CTP"), &Action::finished);
    QVERIFY(fd->resetPartialCounter("CTP", Confirmation::Confirmed).isEmpty());
    QVERIFY(reset.wait());
    fd->parameter("CTP")->refresh();
    f.settle();
    QCOMPARE(fd->parameter("CTP")->number().value(), 0);
    f.simLine->feeder()->setError(5);
    fd->parameter("ECV")->refresh();
    f.settle();
    QVERIFY(fd->errorText().contains(QStringLiteral("5")));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestParameters)

} // namespace tst_parameters
#include "tst_parameters.moc"
