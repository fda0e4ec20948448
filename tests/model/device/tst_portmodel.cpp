// PortModel against the simulator: a port's values by role, its decoded alarm and status, its
// error's words and level, the catalog's groups per port, tool names, and the robot controls.
#include "model/simfixture.h"
#include "testmain.h"

namespace tst_portmodel {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::protocol;
using namespace tipscope::testing;

class TestPortModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void alarmDigitsDecode_data();
    void alarmDigitsDecode();
    void aLatchedAlarmIsReadAndDecoded();
    void portErrorHasItsWordsAndLevel_data();
    void portErrorHasItsWordsAndLevel();
    void listsAreTheCatalogsGroupsOfThePort();
    void valuesAreThePortsOwnByRole();
    void toolsAreNamedFromTheFamilysTable();
    void selectedTemperatureIsWrittenOrRefusedWithTheLimits();
};

void TestPortModel::alarmDigitsDecode_data() {
    QTest::addColumn<int>("value");
    QTest::addColumn<bool>("high");
    QTest::addColumn<bool>("low");
    QTest::addColumn<QString>("text");
    QTest::addColumn<Level>("level");
    QTest::newRow("none") << 0 << false << false << "None" << Level::Ok;
    QTest::newRow("high") << 1 << true << false << "High temperature" << Level::Warning;
    QTest::newRow("low") << 10 << false << true << "Low temperature" << Level::Warning;
    QTest::newRow("both") << 11 << true << true << "High temperature, Low temperature"
                          << Level::Warning;
}

void TestPortModel::alarmDigitsDecode() {
    QFETCH(int, value);
    QFETCH(bool, high);
    QFETCH(bool, low);
    QFETCH(QString, text);
    QFETCH(Level, level);
    const TemperatureAlarm alarm = TemperatureAlarm::fromNumber(value);
    QCOMPARE(alarm.high, high);
    QCOMPARE(alarm.low, low);
    QCOMPARE(alarm.any(), high || low);
    QCOMPARE(alarm.text(), text);
    QCOMPARE(alarm.level(), level);
}

void TestPortModel::aLatchedAlarmIsReadAndDecoded() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    PortModel *port = st->port(2);
    QVERIFY(!port->alarm()); // not read yet
    f.simLine->station()->latchAlarm(2, 10);
    port->parameter(Role::Alarm)->refresh();
    f.settle();
    QCOMPARE(port->alarm(), std::optional<TemperatureAlarm>(TemperatureAlarm{false, true}));
    QCOMPARE(port->alarmFlags(), 10);
    QCOMPARE(port->displayText(Role::Alarm), QStringLiteral("Low temperature alarm"));
    QVERIFY(!st->port(1)->alarm()); // another port's alarm is its own
}

void TestPortModel::portErrorHasItsWordsAndLevel_data() {
    QTest::addColumn<int>("code");
    QTest::addColumn<int>("canonical");
    QTest::addColumn<QString>("text");
    QTest::addColumn<Level>("level");
    QTest::newRow("ok") << 0 << 0 << "OK" << Level::Ok;
    QTest::newRow("no tool") << 4 << 4 << "No tool" << Level::Info;
    QTest::newRow("warning") << 9 << 9 << "Warning: transistor (MOS) overload" << Level::Warning;
    QTest::newRow("error") << 1 << 1 << "Short circuit" << Level::Error;
    QTest::newRow("misprint") << 80000 << 8 << "Stopped by transistor (MOS) overload"
                              << Level::Error;
}

void TestPortModel::portErrorHasItsWordsAndLevel() {
    QFETCH(int, code);
    QFETCH(int, canonical);
    QFETCH(QString, text);
    QFETCH(Level, level);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    PortModel *port = st->port(3);
    QCOMPARE(port->errorLevel(), Level::Unknown);
    f.simLine->station()->setPortError(3, code);
    port->parameter(Role::Error)->refresh();
    f.settle();
    QCOMPARE(port->error(), std::optional<int>(canonical));
    QCOMPARE(port->errorText(), text);
    QCOMPARE(port->errorLevel(), level);
}

void TestPortModel::listsAreTheCatalogsGroupsOfThePort() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    PortModel *port = st->port(2);
    QCOMPARE(codesOf(port->settings()), QList<QByteArray>{"ST2"});
    QCOMPARE(codesOf(port->alarmSettings()), (QList<QByteArray>{"HA2", "LA2", "HD2", "LD2"}));
    QCOMPARE(codesOf(port->toolSettings(4)), (QList<QByteArray>{"A24", "S24", "D24", "H24"}));
    QCOMPARE(codesOf(port->counters()),
             (QList<QByteArray>{"CP2", "CW2", "CS2", "CH2", "CN2", "CC2", "CD2"}));
    QCOMPARE(codesOf(port->liveParameters()), (QList<QByteArray>{"TT2", "PP2", "PS2", "ST2"}));
    QCOMPARE(codesOf(port->statusParameters()),
             (QList<QByteArray>{"CT2", "PE2", "TA2", "ED2", "QT2"}));
    // The robot stations have no alarm delays.
    SimFixture robot(singleDevice(QStringLiteral("DDR")));
    QCOMPARE(codesOf(robot.station()->port(1)->alarmSettings()), (QList<QByteArray>{"HA1", "LA1"}));
}

void TestPortModel::valuesAreThePortsOwnByRole() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    const sim::SimPort &simPort = f.simLine->station()->port(4);
    PortModel *port = st->port(4);
    QCOMPARE(port->parameter(Role::TipTemperature)->code(), QByteArray("TT4"));
    QVERIFY(qAbs(port->tipTemperature().value_or(-100) - simPort.tip) <= 1); // its wobble
    QCOMPARE(port->tool(), std::optional<int>(simPort.tool));
    QCOMPARE(port->status()->mode, PortStatus::Mode(simPort.status));
    QCOMPARE(port->power(), std::optional<qint64>(simPort.power));
    QVERIFY(port->selectedTemperature().has_value());
    QVERIFY(!port->parameter(Role::TransformerTemperature)); // the station's, not a port's
}

void TestPortModel::toolsAreNamedFromTheFamilysTable() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    PortModel *port = st->port(1);
    QCOMPARE(port->toolName(), QStringLiteral("—")); // not read yet
    QCOMPARE(port->toolName(2), QStringLiteral("T245/T470 (TR245/TR470)"));
    QCOMPARE(port->toolName(42), QStringLiteral("tool 42"));
    f.simLine->station()->setTool(1, 0);
    port->parameter(Role::ConnectedTool)->refresh();
    f.settle();
    QCOMPARE(port->toolName(), QStringLiteral("No tool"));
    SimFixture robot(singleDevice(QStringLiteral("DDR")));
    QCOMPARE(robot.station()->port(1)->toolName(2), QStringLiteral("T245"));
}

void TestPortModel::selectedTemperatureIsWrittenOrRefusedWithTheLimits() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    PortModel *port = st->port(1);
    QSignalSpy written(port->parameter(Role::Setpoint), &Parameter::writeFinished);
    QVERIFY(written.isValid());
    QCOMPARE(port->setSelectedTemperature(320), QString());
    QVERIFY(written.wait());
    QVERIFY(written.first().at(0).toBool());
    QCOMPARE(port->selectedTemperature(), std::optional<qint64>(320));
    const qint64 writes = f.simLine->stats().writeRequests;
    const QString why = port->setSelectedTemperature(*st->number(Role::MaxTemperature) + 5);
    QVERIFY2(why.contains(QStringLiteral("allowed is")), qPrintable(why));
    QCoreApplication::processEvents();
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, writes);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestPortModel)

} // namespace tst_portmodel
#include "tst_portmodel.moc"
