// The journal's value types: a device identity's text key reads back as the same identity
// whatever its fields hold, and verdicts, event kinds and severities keep their stable names.
#include "journal/journalevent.h"
#include "model/context/deviceidentity.h"
#include "model/joints/jointrecord.h"
#include "testmain.h"

#include <QTest>

namespace tst_journaltypes {

using namespace tipscope;
using journal::JournalEvent;
using model::DeviceIdentity;
using model::JointVerdict;

class TestJournalTypes : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aDeviceKeyReadsBackAsTheSameIdentity_data();
    void aDeviceKeyReadsBackAsTheSameIdentity();
    void aMalformedDeviceKeyIsRefused_data();
    void aMalformedDeviceKeyIsRefused();
    void verdictsKeepTheirStableNames();
    void everyEventKindAndSeverityReadsBackFromItsName();
    void anEventLogEntryBecomesAJournalEventOfTheSameKind();
};

void TestJournalTypes::aDeviceKeyReadsBackAsTheSameIdentity_data() {
    QTest::addColumn<DeviceIdentity>("identity");
    QTest::addColumn<QString>("key");
    QTest::newRow("serial by-id, addressed")
        << DeviceIdentity{QStringLiteral("/dev/serial/by-id/usb-FTDI_A1-if00-port0"), 1,
                          QStringLiteral("DME-2C"), QStringLiteral("9996780")}
        << QStringLiteral("/dev/serial/by-id/usb-FTDI_A1-if00-port0|01|DME-2C|9996780");
    QTest::newRow("tcp, without address")
        << DeviceIdentity{QStringLiteral("10.0.0.7:4001"), std::nullopt, QStringLiteral("SFR"),
                          QString()}
        << QStringLiteral("10.0.0.7:4001||SFR|");
    QTest::newRow("separators inside fields")
        << DeviceIdentity{QStringLiteral("a|b\\c"), 99, QStringLiteral("x|"), QStringLiteral("\\")}
        << QStringLiteral("a\\|b\\\\c|99|x\\||\\\\");
}

void TestJournalTypes::aDeviceKeyReadsBackAsTheSameIdentity() {
    QFETCH(DeviceIdentity, identity);
    QFETCH(QString, key);
    QCOMPARE(identity.key(), key);
    const std::optional<DeviceIdentity> back = DeviceIdentity::fromKey(key);
    QVERIFY(back.has_value());
    QVERIFY(*back == identity);
}

void TestJournalTypes::aMalformedDeviceKeyIsRefused_data() {
    QTest::addColumn<QString>("key");
    QTest::newRow("three fields") << QStringLiteral("/dev/ttyUSB0|01|DME");
    QTest::newRow("five fields") << QStringLiteral("/dev/ttyUSB0|01|DME|1|2");
    QTest::newRow("address not a number") << QStringLiteral("/dev/ttyUSB0|x1|DME|1");
    QTest::newRow("dangling escape") << QStringLiteral("/dev/ttyUSB0|01|DME|1\\");
}

void TestJournalTypes::aMalformedDeviceKeyIsRefused() {
    QFETCH(QString, key);
    QVERIFY(!DeviceIdentity::fromKey(key).has_value());
}

void TestJournalTypes::verdictsKeepTheirStableNames() {
    QCOMPARE(model::jointVerdictName(JointVerdict::Ok), QStringLiteral("ok"));
    QCOMPARE(model::jointVerdictName(JointVerdict::SlowRecovery), QStringLiteral("slow recovery"));
    QCOMPARE(model::jointVerdictName(JointVerdict::TooDeep), QStringLiteral("too deep"));
    QCOMPARE(model::jointVerdictName(JointVerdict::Incomplete), QStringLiteral("incomplete"));
    for (const JointVerdict verdict : model::kJointVerdicts)
        QCOMPARE(model::jointVerdictFromName(model::jointVerdictName(verdict)), verdict);
    QVERIFY(!model::jointVerdictFromName(QStringLiteral("OK")).has_value());
}

void TestJournalTypes::everyEventKindAndSeverityReadsBackFromItsName() {
    QStringList names;
    for (const JournalEvent::Kind kind : journal::kJournalEventKinds) {
        const QString name = JournalEvent::kindName(kind);
        QVERIFY2(!name.isEmpty() && !names.contains(name), qPrintable(name));
        names.append(name);
        QCOMPARE(JournalEvent::kindFromName(name), kind);
    }
    QCOMPARE(JournalEvent::kindName(JournalEvent::Kind::ProfileApply),
             QStringLiteral("profile apply"));
    for (const auto severity : {JournalEvent::Severity::Info, JournalEvent::Severity::Warning,
                                JournalEvent::Severity::Error})
        QCOMPARE(JournalEvent::severityFromName(JournalEvent::severityName(severity)), severity);
}

void TestJournalTypes::anEventLogEntryBecomesAJournalEventOfTheSameKind() {
    const model::Event logged{QDateTime::fromMSecsSinceEpoch(1'700'000'000'123),
                              model::Event::Kind::PortError, model::Event::Severity::Error,
                              QStringLiteral("DME-2C at 01, port 2"),
                              QStringLiteral("Short circuit")};
    const DeviceIdentity device{QStringLiteral("/dev/ttyUSB0"), 1, QStringLiteral("DME-2C"),
                                QStringLiteral("1")};
    const JournalEvent event = JournalEvent::fromEventLog(logged, device, 2);
    QCOMPARE(event.kind, JournalEvent::Kind::PortError);
    QCOMPARE(JournalEvent::kindName(event.kind), model::Event::kindName(logged.kind));
    QCOMPARE(event.severity, JournalEvent::Severity::Error);
    QVERIFY(event.device == device);
    QCOMPARE(event.port, std::optional<int>(2));
    QCOMPARE(event.timeMs, 1'700'000'000'123);
    QCOMPARE(event.text, QStringLiteral("Short circuit"));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJournalTypes)

} // namespace tst_journaltypes
#include "tst_journaltypes.moc"
