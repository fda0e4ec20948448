// Session end to end: it identifies a device at an address the probe does not try by asking
// the catalog's model-name command (and says why when the device refuses to name itself), records
// port and feeder samples from the values their roles name, and builds its models from the catalog
// it was given. Its devices know whether the line
// is up, and a write the lost line refused is no longer an error once the line is back.
#include "model/session.h"
#include "testmain.h"

#include "link/simtransport.h"

#include "support/ptyfixtures.h"
#include "support/testcatalog.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_session {

using namespace tipscope;
using namespace tipscope::model;
using protocol::Role;

namespace {
constexpr int kConnectMs = 60000;

Session::Settings demoSettings() {
    Session::Settings settings;
    settings.line.kind = link::LineSettings::Kind::Demo;
    return settings;
}

// Settings for the device at `address` of the tipscope-sim serving at `where` ("HOST:PORT").
Session::Settings simSettings(const QString &where, int address) {
    Session::Settings settings;
    settings.line.kind = link::LineSettings::Kind::Tcp;
    settings.line.tcpHost = where.section(QLatin1Char(':'), 0, 0);
    settings.line.tcpPort = quint16(where.section(QLatin1Char(':'), 1).toUInt());
    settings.addressing = Session::Addressing::With;
    settings.targetAddress = address;
    return settings;
}

qint32 lastValue(const TelemetryBuffer &buffer, const QString &series) {
    return buffer.valueAt(buffer.seriesIndex(series), buffer.lastTime()).value().value;
}
} // namespace

class TestSession : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aDeviceAtAnAddressNoProbeTriesIsIdentifiedByItsModelName();
    void aDeviceThatRefusesToNameItselfIsReportedWithItsNak();
    void samplesCarryTheValuesTheirRolesName();
    void modelsAreBuiltFromTheSessionsCatalog();
    void aLostLineMakesEveryValueStaleUntilItIsBack();
    void aWriteTheLostLineRefusedIsNoErrorOnceTheLineIsBack();
};

void TestSession::aDeviceAtAnAddressNoProbeTriesIsIdentifiedByItsModelName() {
    testing::SimProcess sim;
    QString error;
    const QString where =
        sim.start({QStringLiteral("--model"), QStringLiteral("DDE"), QStringLiteral("--address"),
                   QStringLiteral("42"), QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")},
                  &error);
    QVERIFY2(!where.isEmpty(), qPrintable(error));
    Session session;
    session.connectTo(simSettings(where, 42));
    QTRY_VERIFY_WITH_TIMEOUT(session.state() == Session::State::Connected, kConnectMs);
    QVERIFY(session.station());
    QCOMPARE(session.station()->family(), QStringLiteral("DDE"));
    QCOMPARE(session.station()->address(), std::optional<int>(42));
    QCOMPARE(session.station()->info().model, QStringLiteral("DDE-2C"));
}

void TestSession::aDeviceThatRefusesToNameItselfIsReportedWithItsNak() {
    testing::SimProcess sim;
    QString error;
    const QString where =
        sim.start({QStringLiteral("--model"), QStringLiteral("DME"), QStringLiteral("--nak"),
                   QStringLiteral("4"), QStringLiteral("--nak-for"), QStringLiteral("SMN"),
                   QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")},
                  &error);
    QVERIFY2(!where.isEmpty(), qPrintable(error));
    Session session;
    session.connectTo(simSettings(where, 1));
    QTRY_VERIFY_WITH_TIMEOUT(session.state() == Session::State::Connected, kConnectMs);
    QVERIFY(session.devices().isEmpty());
    const QString text = session.stateText();
    QVERIFY2(text.contains(QStringLiteral("the device at address 01 did not identify itself")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("NAK 00004")), qPrintable(text));
}

void TestSession::samplesCarryTheValuesTheirRolesName() {
    Session session;
    session.connectTo(demoSettings());
    QTRY_VERIFY_WITH_TIMEOUT(session.station() && session.feeder(), kConnectMs);
    const TelemetryBuffer *port =
        session.telemetry().buffer(TelemetryRecorder::keyOf(*session.station(), 1));
    const TelemetryBuffer *feeder =
        session.telemetry().buffer(TelemetryRecorder::keyOf(*session.feeder(), 0));
    QVERIFY(port && feeder);
    QTRY_VERIFY_WITH_TIMEOUT(!port->isEmpty() && !feeder->isEmpty(), kConnectMs);
    StationModel *st = session.station();
    QCOMPARE(lastValue(*port, QStringLiteral("setpoint")), qint32(*st->number(Role::Setpoint, 1)));
    QCOMPARE(lastValue(*port, QStringLiteral("status")), qint32(*st->number(Role::Status, 1)));
    QCOMPARE(lastValue(*feeder, QStringLiteral("speed")), qint32(*session.feeder()->feedSpeed()));
}

void TestSession::modelsAreBuiltFromTheSessionsCatalog() {
    const auto catalog = testing::catalogWith(testing::newCommandEntries());
    QVERIFY2(catalog, qPrintable(catalog.error()));
    Session session(*catalog);
    session.connectTo(demoSettings());
    QTRY_VERIFY_WITH_TIMEOUT(session.station() && session.feeder(), kConnectMs);
    QCOMPARE(&session.station()->catalog(), &*catalog);
    QCOMPARE(&session.feeder()->catalog(), &*catalog);
    QVERIFY(session.station()->parameter("BRT"));
    QVERIFY(session.feeder()->action("CJP"));
}

void TestSession::aLostLineMakesEveryValueStaleUntilItIsBack() {
    Session session;
    session.connectTo(demoSettings());
    QTRY_VERIFY_WITH_TIMEOUT(session.state() == Session::State::Connected, kConnectMs);
    StationModel *st = session.station();
    Parameter *tip = st->parameter(Role::TipTemperature, 1);
    QTRY_VERIFY_WITH_TIMEOUT(tip->value().has_value(), kConnectMs);
    QVERIFY(st->isLineUp());
    QVERIFY(tip->isCurrent());
    QSignalSpy down(st, &DeviceModel::lineUpChanged);
    QVERIFY(down.isValid());
    auto *transport = qobject_cast<link::SimTransport *>(&session.line()->transport());
    transport->setPlugged(false);
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), Session::State::Retrying, kConnectMs);
    QVERIFY(!st->isLineUp());
    QCOMPARE(down.count(), 1);
    QVERIFY(!tip->isCurrent());
    QVERIFY(tip->value().has_value()); // the last reading is kept, with its time
    QVERIFY(tip->lastUpdate().isValid());
    QVERIFY(!st->writesUnavailableReason().isEmpty());
    transport->setPlugged(true);
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), Session::State::Connected, kConnectMs);
    QVERIFY(st->isLineUp());
    QVERIFY(tip->isCurrent());
    QVERIFY(st->writesUnavailableReason().isEmpty());
}

void TestSession::aWriteTheLostLineRefusedIsNoErrorOnceTheLineIsBack() {
    Session session;
    session.connectTo(demoSettings());
    QTRY_VERIFY_WITH_TIMEOUT(session.state() == Session::State::Connected, kConnectMs);
    Parameter *mat = session.station()->parameter(Role::MaxTemperature);
    QVERIFY(mat);
    mat->refresh();
    QTRY_VERIFY_WITH_TIMEOUT(mat->value().has_value(), kConnectMs);
    auto *transport = qobject_cast<link::SimTransport *>(&session.line()->transport());
    transport->setPlugged(false);
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), Session::State::Retrying, kConnectMs);
    const qint64 wanted = *mat->number() == 450 ? 400 : 450;
    QCOMPARE(mat->setEdit(wanted), QString());
    mat->apply();
    QTRY_COMPARE_WITH_TIMEOUT(mat->state(), Parameter::State::Failed, kConnectMs);
    QVERIFY2(mat->failure().contains(QStringLiteral("not connected")), qPrintable(mat->failure()));
    // A read that fails as well leaves the write failed, never "in sync".
    mat->refresh();
    QTRY_COMPARE_WITH_TIMEOUT(mat->state(), Parameter::State::Failed, kConnectMs);
    QVERIFY2(mat->failure().contains(QStringLiteral("not connected")), qPrintable(mat->failure()));
    transport->setPlugged(true);
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), Session::State::Connected, kConnectMs);
    QCOMPARE(mat->state(), Parameter::State::Edited); // the edit is kept, to apply again
    QCOMPARE(mat->failure(), QString());
    QCOMPARE(mat->edit(), std::optional<qint64>(wanted));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSession)

} // namespace tst_session
#include "tst_session.moc"
