// The CFX messages of a station's endpoint: names and fields as the IPC's SDK has them, the
// SEMI E10 mapping, handles, and faults tied from the error that raised them to its clearing.
#include "cfx/cfxmessages.h"
#include "testmain.h"

#include <QJsonArray>
#include <QTest>

namespace tst_cfxmessages {

using namespace tipscope::cfx;
using tipscope::journal::JournalEvent;

class TstCfxMessages : public QObject {
    Q_OBJECT

    static JournalEvent portError(JournalEvent::Severity severity, const QString &text) {
        JournalEvent event;
        event.kind = JournalEvent::Kind::PortError;
        event.severity = severity;
        event.device.line = QStringLiteral("/dev/ttyUSB0");
        event.device.address = 1;
        event.device.model = QStringLiteral("DDE");
        event.port = 2;
        event.timeMs = 1796568301250;
        event.text = text;
        return event;
    }

private Q_SLOTS:
    void stationConditionsMapToE10States_data() {
        QTest::addColumn<StationCondition>("condition");
        QTest::addColumn<int>("state");
        QTest::newRow("working") << StationCondition::Working << 1100;
        QTest::newRow("in the stand") << StationCondition::InStand << 2200;
        QTest::newRow("sleep") << StationCondition::Sleep << 2100;
        QTest::newRow("hibernation") << StationCondition::Hibernation << 2100;
        QTest::newRow("error") << StationCondition::Error << 5000;
        QTest::newRow("link lost") << StationCondition::LinkLost << 2500;
    }
    void stationConditionsMapToE10States() {
        QFETCH(StationCondition, condition);
        QFETCH(int, state);
        QCOMPARE(int(e10StateOf(condition)), state);
    }

    void stateChangeWritesStatesAsNumbersAndItsDuration() {
        const Message message =
            stationStateChanged(StationCondition::InStand, 85000, StationCondition::Working, {});
        QCOMPARE(message.name, QStringLiteral("CFX.ResourcePerformance.StationStateChanged"));
        QCOMPARE(message.body.value(QStringLiteral("OldState")).toString(), QStringLiteral("2200"));
        QCOMPARE(message.body.value(QStringLiteral("NewState")).toString(), QStringLiteral("1100"));
        QCOMPARE(message.body.value(QStringLiteral("OldStateDuration")).toString(),
                 QStringLiteral("00:01:25"));
        QVERIFY(message.body.value(QStringLiteral("RelatedFault")).isNull());
        const Message unknown = stationStateChanged(StationCondition::LinkLost, std::nullopt,
                                                    StationCondition::Sleep, {});
        QVERIFY(unknown.body.value(QStringLiteral("OldStateDuration")).isNull());
    }

    void handleIsVendorModelUnitInSafeCharacters() {
        QCOMPARE(
            endpointHandle(QStringLiteral("JBC"), QStringLiteral("DDE"), QStringLiteral("0012A3")),
            QStringLiteral("JBC.DDE.0012A3"));
        QCOMPARE(endpointHandle(QStringLiteral("JBC"), QStringLiteral("DDE 2.0"),
                                QStringLiteral("line 1/3")),
                 QStringLiteral("JBC.DDE_2_0.line_1_3"));
        QCOMPARE(endpointHandle(QStringLiteral("JBC"), QString(), QStringLiteral("x")),
                 QStringLiteral("JBC.unknown.x"));
    }

    void endpointMessagesNameTheirHandle() {
        const Message connected =
            endpointConnected(QStringLiteral("JBC.DDE.1"), QStringLiteral("amqp://broker:5672"),
                              QStringLiteral("/queue/JBC.DDE.1"));
        QCOMPARE(connected.name, QStringLiteral("CFX.EndpointConnected"));
        QCOMPARE(connected.body.value(QStringLiteral("CFXHandle")).toString(),
                 QStringLiteral("JBC.DDE.1"));
        QCOMPARE(connected.body.value(QStringLiteral("RequestTargetAddress")).toString(),
                 QStringLiteral("/queue/JBC.DDE.1"));
        const Message beat = heartbeat(QStringLiteral("JBC.DDE.1"), 60000, QJsonArray());
        QCOMPARE(beat.name, QStringLiteral("CFX.Heartbeat"));
        QCOMPARE(beat.body.value(QStringLiteral("HeartbeatFrequency")).toString(),
                 QStringLiteral("00:01:00"));
        QVERIFY(beat.body.value(QStringLiteral("ActiveFaults")).isArray());
        QCOMPARE(endpointShuttingDown(QStringLiteral("JBC.DDE.1")).name,
                 QStringLiteral("CFX.EndpointShuttingDown"));
    }

    void onlyErrorEventsRaiseOrClearFaults() {
        QVERIFY(isFaultEvent(portError(JournalEvent::Severity::Error, QStringLiteral("x"))));
        JournalEvent status = portError(JournalEvent::Severity::Info, QStringLiteral("x"));
        status.kind = JournalEvent::Kind::Status;
        QVERIFY(!isFaultEvent(status));
    }

    void faultCarriesItsOccurrenceAndEnumsAsNames() {
        const QUuid occurrence = QUuid::createUuid();
        const QJsonObject f = fault(
            portError(JournalEvent::Severity::Error, QStringLiteral("Short circuit")), occurrence);
        QCOMPARE(f.value(QStringLiteral("FaultOccurrenceId")).toString(),
                 occurrence.toString(QUuid::WithoutBraces));
        QCOMPARE(f.value(QStringLiteral("Severity")).toString(), QStringLiteral("Error"));
        QCOMPARE(f.value(QStringLiteral("Cause")).toString(), QStringLiteral("ProcessError"));
        QCOMPARE(f.value(QStringLiteral("FaultCode")).toString(), QStringLiteral("port error 2"));
        QCOMPARE(f.value(QStringLiteral("Description")).toString(),
                 QStringLiteral("Short circuit"));
        QCOMPARE(f.value(QStringLiteral("SideLocation")).toString(), QStringLiteral("Unknown"));
        QCOMPARE(f.value(QStringLiteral("OccurredAt")).toString(),
                 QStringLiteral("2026-12-06T14:45:01.250Z"));
        const Message occurred = faultOccurred(f);
        QCOMPARE(occurred.name, QStringLiteral("CFX.ResourcePerformance.FaultOccurred"));
        const Message cleared = faultCleared(occurrence);
        QCOMPARE(cleared.name, QStringLiteral("CFX.ResourcePerformance.FaultCleared"));
        QCOMPARE(cleared.body.value(QStringLiteral("FaultOccurrenceId")).toString(),
                 f.value(QStringLiteral("FaultOccurrenceId")).toString());
    }

    void aFaultAndItsClearingShareAPlace() {
        const JournalEvent raised = portError(JournalEvent::Severity::Error, QStringLiteral("x"));
        JournalEvent cleared = portError(JournalEvent::Severity::Info, QStringLiteral("cleared"));
        QCOMPARE(faultPlace(raised), faultPlace(cleared));
        cleared.port = 1;
        QVERIFY(faultPlace(raised) != faultPlace(cleared));
    }

    void requestsGetTheSdkAnswers() {
        const Message there = areYouThereResponse(QStringLiteral("JBC.DDE.1"), QString(),
                                                  QStringLiteral("/queue/JBC.DDE.1"));
        QCOMPARE(there.name, QStringLiteral("CFX.AreYouThereResponse"));
        QCOMPARE(there.body.value(QStringLiteral("Result"))
                     .toObject()
                     .value(QStringLiteral("Result"))
                     .toString(),
                 QStringLiteral("Success"));
        const Message refused = notSupportedResponse(QStringLiteral("CFX.Production.Hold"));
        QCOMPARE(refused.name, QStringLiteral("CFX.NotSupportedResponse"));
        QCOMPARE(refused.body.value(QStringLiteral("RequestResult"))
                     .toObject()
                     .value(QStringLiteral("Result"))
                     .toString(),
                 QStringLiteral("Failed"));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TstCfxMessages)

} // namespace tst_cfxmessages
#include "tst_cfxmessages.moc"
