// StationModel against the simulator: its lists follow the catalog's groups, its values are
// found by role, its errors carry their words and level, its actions are found by role and a
// missing one is named, and changes of error, alarm and status reach the event log.
#include "model/simfixture.h"
#include "testmain.h"

#include "support/testcatalog.h"

namespace tst_stationmodel {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::protocol;
using namespace tipscope::testing;

class TestStationModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void stationSettingsAreTheCatalogsStationGroup_data();
    void stationSettingsAreTheCatalogsStationGroup();
    void valuesAreFoundByRoleOnTheirPort();
    void aValueTheFamilyLacksIsNullAndShownAsADash();
    void stationErrorHasItsWordsAndLevel_data();
    void stationErrorHasItsWordsAndLevel();
    void fuseIsReadWhereTheFamilyHasOne();
    void anActionTheFamilyLacksIsRefusedByName();
    void errorAlarmAndStatusChangesReachTheEventLog();
    void anotherCatalogsEntriesBecomeParameters();
};

void TestStationModel::stationSettingsAreTheCatalogsStationGroup_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<QList<QByteArray>>("codes");
    QTest::newRow("DME") << "DME" << QList<QByteArray>{"MAT", "MIT"};
    QTest::newRow("DDR") << "DDR" << QList<QByteArray>{"MAT", "MIT", "PLM"};
}

void TestStationModel::stationSettingsAreTheCatalogsStationGroup() {
    QFETCH(QString, family);
    QFETCH(QList<QByteArray>, codes);
    SimFixture f(singleDevice(family));
    auto st = f.station();
    QCOMPARE(codesOf(st->stationSettings()), codes);
    QVERIFY(st->dispensingSettings().isEmpty());
    QVERIFY(st->counters().isEmpty()); // a station's counters are its ports'
}

void TestStationModel::valuesAreFoundByRoleOnTheirPort() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    QCOMPARE(st->parameter(Role::TipTemperature, 3)->code(), QByteArray("TT3"));
    QCOMPARE(st->parameter(Role::Error)->code(), QByteArray("SER"));
    QCOMPARE(st->parameter(Role::Error, 2)->code(), QByteArray("PE2"));
    QCOMPARE(st->parameter(Role::TransformerTemperature)->code(), QByteArray("TT0"));
    QVERIFY(!st->parameter(Role::TipTemperature)); // a port's value, not the station's
    QVERIFY(!st->parameter(Role::TipTemperature, 5));
    QCOMPARE(st->action(Role::SaveToMemory)->code(), QByteArray("NVS"));
    st->refreshAll();
    f.settle();
    QCOMPARE(st->number(Role::Setpoint, 1), st->port(1)->selectedTemperature());
    QCOMPARE(st->transformerTemperature(), st->parameter("TT0")->number());
    QVERIFY(st->transformerTemperature().value_or(0) > 0);
}

void TestStationModel::aValueTheFamilyLacksIsNullAndShownAsADash() {
    SimFixture f(singleDevice(QStringLiteral("DDR")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    QVERIFY(!st->parameter(Role::Fuse)); // only the UCR and the ALE have a fuse
    QVERIFY(!st->fusePresent());
    QVERIFY(!st->number(Role::Fuse));
    QCOMPARE(st->displayText(Role::Fuse), QStringLiteral("—"));
    QVERIFY(!st->parameter(Role::DispensedLength, 1));
}

void TestStationModel::stationErrorHasItsWordsAndLevel_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("text");
    QTest::addColumn<Level>("level");
    QTest::newRow("none") << "DME" << 0 << "OK" << Level::Ok;
    QTest::newRow("warning") << "DME" << 7 << "Warning: transformer overload" << Level::Warning;
    QTest::newRow("error") << "DME" << 2 << "Temperature sensor error" << Level::Error;
    QTest::newRow("robot station")
        << "DDR" << 1 << "Stopped by transformer overload" << Level::Error;
}

void TestStationModel::stationErrorHasItsWordsAndLevel() {
    QFETCH(QString, family);
    QFETCH(int, code);
    QFETCH(QString, text);
    QFETCH(Level, level);
    SimFixture f(singleDevice(family));
    auto st = f.station();
    QCOMPARE(st->stationErrorLevel(), Level::Unknown);
    QCOMPARE(st->stationErrorText(), QStringLiteral("—"));
    f.simLine->station()->setStationError(code);
    st->parameter(Role::Error)->refresh();
    f.settle();
    QCOMPARE(st->stationError(), std::optional<int>(code));
    QCOMPARE(st->stationErrorText(), text);
    QCOMPARE(st->stationErrorLevel(), level);
}

void TestStationModel::fuseIsReadWhereTheFamilyHasOne() {
    SimFixture f(singleDevice(QStringLiteral("UCR")));
    auto st = f.station();
    st->parameter(Role::Fuse)->refresh();
    f.settle();
    QCOMPARE(st->fusePresent(), std::optional<bool>(true));
    f.simLine->station()->setFuse(false);
    st->parameter(Role::Fuse)->refresh();
    f.settle();
    QCOMPARE(st->fusePresent(), std::optional<bool>(false));
}

void TestStationModel::anActionTheFamilyLacksIsRefusedByName() {
    SimFixture f(singleDevice(QStringLiteral("DDR")));
    auto st = f.station();
    const qint64 before = f.simLine->stats().writeRequests;
    const QString why = st->restart(Confirmation::Confirmed);
    QVERIFY2(why.contains(QStringLiteral("does not support RST")), qPrintable(why));
    QVERIFY(st->ignoreFuseError(Confirmation::Confirmed).contains(QStringLiteral("IFE")));
    QVERIFY(!st->factoryReset(Confirmation::None).isEmpty()); // dangerous: not confirmed
    QCoreApplication::processEvents();
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, before);
}

void TestStationModel::errorAlarmAndStatusChangesReachTheEventLog() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    EventLog log;
    st->setEventLog(&log);
    st->refreshAll();
    f.settle();
    log.clear();
    f.simLine->station()->setStationError(7);
    f.simLine->station()->setPortError(2, 9);
    f.simLine->station()->latchAlarm(3, 1);
    f.simLine->station()->setStatus(4, 1);
    for (Parameter *p : {st->parameter(Role::Error), st->parameter(Role::Error, 2),
                         st->parameter(Role::Alarm, 3), st->parameter(Role::Status, 4)})
        p->refresh();
    f.settle();
    QMap<Event::Kind, Event> byKind;
    for (const Event &e : log.events())
        byKind.insert(e.kind, e);
    QCOMPARE(byKind.value(Event::Kind::StationError).severity, Event::Severity::Warning);
    QCOMPARE(byKind.value(Event::Kind::StationError).source, st->displayName());
    QCOMPARE(byKind.value(Event::Kind::PortError).text,
             QStringLiteral("Warning: transistor (MOS) overload"));
    QVERIFY(byKind.value(Event::Kind::PortError).source.endsWith(QStringLiteral("port 2")));
    QCOMPARE(byKind.value(Event::Kind::Alarm).text, QStringLiteral("High temperature alarm"));
    QCOMPARE(byKind.value(Event::Kind::Status).text, QStringLiteral("Working → Stand"));
    QVERIFY(byKind.value(Event::Kind::Status).source.endsWith(QStringLiteral("port 4")));
    // The words are translated; the wire's numbers beside them are for programs.
    QCOMPARE(byKind.value(Event::Kind::Status).details,
             (QJsonObject{{QStringLiteral("from"), 0}, {QStringLiteral("to"), 1}}));
}

void TestStationModel::anotherCatalogsEntriesBecomeParameters() {
    const auto catalog = catalogWith(newCommandEntries());
    QVERIFY2(catalog, qPrintable(catalog.error()));
    SimFixture f(singleDevice(QStringLiteral("DME")));
    StationModel st(f.line->queue(), SimFixture::infoOf(*f.simLine->devices().first()), *catalog);
    QCOMPARE(&st.catalog(), &*catalog);
    QCOMPARE(codesOf(st.stationSettings()), (QList<QByteArray>{"MAT", "MIT", "BRT"}));
    QCOMPARE(codesOf(st.port(2)->counters()).last(), QByteArray("CK2"));
    // The simulator knows only the built-in catalog: it refuses the new code, and the log says
    // so; the value stays unknown.
    EventLog log;
    st.setEventLog(&log);
    Parameter *brt = st.parameter("BRT");
    brt->refresh();
    f.settle();
    QCOMPARE(brt->state(), Parameter::State::Unknown);
    QCOMPARE(log.size(), 1);
    const QString text = log.events().first().text;
    QVERIFY2(text.contains(QStringLiteral("Display brightness (BRT)")) &&
                 text.contains(QStringLiteral("not accepted")),
             qPrintable(text));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestStationModel)

} // namespace tst_stationmodel
#include "tst_stationmodel.moc"
