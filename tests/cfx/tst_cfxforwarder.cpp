// The journal's station, port and feeder errors forwarded as CFX faults to a real RabbitMQ and
// read by the independent Python consumer: in the journal's order, each message's UniqueID its
// event's id, a clearing tied to its error, every event marked sent only once accepted, and
// nothing lost or sent under two ids across a broker outage; and the work context's boards as
// per-board transactions, a board's messages waiting for the joints still open at its end.
#include "cfx/amqpsender.h"
#include "cfx/cfxforwarder.h"
#include "cfx/cfxmessages.h"
#include "cfxtesting.h"
#include "journalfixture.h"
#include "testmain.h"

#include "journal/journalreader.h"
#include "model/context/workcontextjson.h"

#include <QDateTime>
#include <QJsonArray>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_cfxforwarder {

using namespace tipscope;
using namespace tipscope::cfx;
using journal::JournalEvent;
using testing::CfxConsumer;
using testing::portEvent;
using testing::RabbitMqBroker;

class TstCfxForwarder : public QObject {
    Q_OBJECT

    std::unique_ptr<RabbitMqBroker> m_broker;

    static QString handleOf(const model::DeviceIdentity &device) {
        // Each sample device is on a line of its own, at the same address.
        return endpointHandle(QStringLiteral("JBC"), device.model,
                              QStringLiteral("%1-%2")
                                  .arg(device.line.section(QLatin1Char('/'), -1))
                                  .arg(device.address.value_or(0)));
    }

    static qint64 unsentCount(const QString &path) {
        journal::JournalReader reader;
        if (!reader.open(path))
            return -1;
        const auto events = reader.unsentEvents(0, 1000, journal::SentChannel::Cfx);
        return events ? events->size() : -1;
    }

    static JournalEvent contextChange(const model::WorkContext &from, const model::WorkContext &to,
                                      qint64 timeMs) {
        JournalEvent event;
        event.kind = JournalEvent::Kind::ContextChange;
        event.timeMs = timeMs;
        event.text = to.boardSerial;
        event.details = {{QStringLiteral("from"), model::workContextToJson(from)},
                         {QStringLiteral("to"), model::workContextToJson(to)}};
        return event;
    }

    static QJsonObject envelopeAt(const CfxConsumer &consumer, int i) {
        return consumer.messages().at(i).value(QStringLiteral("envelope")).toObject();
    }
    static QString bodyField(const QJsonObject &envelope, const QString &name) {
        return envelope.value(QStringLiteral("MessageBody")).toObject().value(name).toString();
    }

private Q_SLOTS:
    void initTestCase() { testing::startCfxBroker(m_broker); }
    void cleanupTestCase() { m_broker.reset(); }

    void faultsArriveInOrderTiedToTheirClearing() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
        journal::Journal journal(path, testing::quickOptions());
        QVERIFY(testing::waitOpened(journal));
        const QUuid raised = journal.append(portEvent(
            JournalEvent::Kind::PortError, JournalEvent::Severity::Error, 2, testing::kT0));
        JournalEvent status = portEvent(JournalEvent::Kind::Status, JournalEvent::Severity::Info, 2,
                                        testing::kT0 + 10);
        journal.append(status);
        const QUuid cleared = journal.append(portEvent(
            JournalEvent::Kind::PortError, JournalEvent::Severity::Info, 2, testing::kT0 + 20));
        CfxConsumer consumer;
        QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), 2),
                 qPrintable(consumer.output()));
        AmqpSender sender;
        CfxForwarder forwarder(journal, sender, handleOf, Codec::Gzip);
        sender.start(
            testing::quickSenderSettings(*m_broker, QStringLiteral("/exchange/amq.topic")));
        QVERIFY2(consumer.finish(), qPrintable(consumer.output()));
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        QCOMPARE(consumer.messages().size(), 2);
        const QJsonObject first = envelopeAt(consumer, 0), second = envelopeAt(consumer, 1);
        QCOMPARE(first.value(QStringLiteral("MessageName")).toString(),
                 QStringLiteral("CFX.ResourcePerformance.FaultOccurred"));
        QCOMPARE(first.value(QStringLiteral("UniqueID")).toString(),
                 raised.toString(QUuid::WithoutBraces));
        QCOMPARE(first.value(QStringLiteral("Source")).toString(), handleOf(status.device));
        QCOMPARE(second.value(QStringLiteral("MessageName")).toString(),
                 QStringLiteral("CFX.ResourcePerformance.FaultCleared"));
        QCOMPARE(second.value(QStringLiteral("UniqueID")).toString(),
                 cleared.toString(QUuid::WithoutBraces));
        QCOMPARE(bodyField(second, QStringLiteral("FaultOccurrenceId")),
                 raised.toString(QUuid::WithoutBraces));
        // The status change has no CFX fault: marked at once, with the two accepted ones.
        QTRY_COMPARE_WITH_TIMEOUT(unsentCount(path), qint64(0), 20000);
        QCOMPARE(forwarder.acceptedCount(), qint64(2));
        // Raised and cleared: the heartbeat says no fault is active, not that it cannot tell.
        QCOMPARE(forwarder.activeFaults(handleOf(status.device)), QJsonValue(QJsonArray()));
    }

    // The heartbeat's ActiveFaults after a restart: what the journal raised and did not clear,
    // each at its station's endpoint, with the occurrence its FaultOccurred carried. Read from
    // the journal alone: no broker is needed to know it.
    void theActiveFaultsAreWhatTheJournalRaisedAndDidNotClear() {
        QTemporaryDir dir;
        journal::Journal journal(dir.filePath(QStringLiteral("journal.sqlite")),
                                 testing::quickOptions());
        QVERIFY(testing::waitOpened(journal));
        const QUuid open = journal.append(portEvent(
            JournalEvent::Kind::PortError, JournalEvent::Severity::Error, 2, testing::kT0));
        journal.append(portEvent(JournalEvent::Kind::PortError, JournalEvent::Severity::Error, 3,
                                 testing::kT0 + 10));
        journal.append(portEvent(JournalEvent::Kind::Status, JournalEvent::Severity::Info, 2,
                                 testing::kT0 + 15));
        journal.append(portEvent(JournalEvent::Kind::PortError, JournalEvent::Severity::Info, 3,
                                 testing::kT0 + 20));
        JournalEvent other = portEvent(JournalEvent::Kind::StationError,
                                       JournalEvent::Severity::Warning, 0, testing::kT0 + 30);
        other.port.reset();
        other.device = testing::sampleDevice(1);
        const QUuid otherOpen = journal.append(other);
        QVERIFY(journal.flush());

        AmqpSender sender; // never started: the faults come from the journal
        CfxForwarder forwarder(journal, sender, handleOf, Codec::Gzip);
        const QJsonValue here = forwarder.activeFaults(handleOf(testing::sampleDevice(0)));
        QVERIFY(here.isArray());
        QCOMPARE(here.toArray().size(), 1);
        const QJsonObject fault = here.toArray().first().toObject();
        QCOMPARE(fault.value(QStringLiteral("FaultOccurrenceId")).toString(),
                 open.toString(QUuid::WithoutBraces));
        QCOMPARE(fault.value(QStringLiteral("Severity")).toString(), QStringLiteral("Error"));
        const QJsonArray there = forwarder.activeFaults(handleOf(other.device)).toArray();
        QCOMPARE(there.size(), 1);
        QCOMPARE(there.first().toObject().value(QStringLiteral("FaultOccurrenceId")).toString(),
                 otherOpen.toString(QUuid::WithoutBraces));
        QCOMPARE(forwarder.activeFaults(QStringLiteral("JBC.DME.nobody")),
                 QJsonValue(QJsonArray()));
    }

    void anOutageLosesNothingAndSendsEachOnce() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
        journal::Journal journal(path, testing::quickOptions());
        QVERIFY(testing::waitOpened(journal));
        // A queue of its own keeps what arrives while nobody reads it, across the outage.
        const QString queue = QStringLiteral("/queue/tipscope-cfx-outage");
        AmqpSender sender;
        CfxForwarder forwarder(journal, sender, handleOf, Codec::Raw);
        QSignalSpy lost(&sender, &AmqpSender::disconnected);
        sender.start(testing::quickSenderSettings(*m_broker, queue));
        QTRY_VERIFY_WITH_TIMEOUT(sender.state() == AmqpSender::State::Connected, 20000);
        QSet<QString> journaled;
        const auto appendPair = [&](int i) {
            const qint64 t = testing::kT0 + 1000 * i;
            journaled << journal
                             .append(portEvent(JournalEvent::Kind::PortError,
                                               JournalEvent::Severity::Error, 1, t))
                             .toString(QUuid::WithoutBraces)
                      << journal
                             .append(portEvent(JournalEvent::Kind::PortError,
                                               JournalEvent::Severity::Info, 1, t + 500))
                             .toString(QUuid::WithoutBraces);
        };
        for (int i = 0; i < 10; ++i)
            appendPair(i);
        QString error;
        QVERIFY2(m_broker->pause(&error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(lost.size(), 1, 20000);
        for (int i = 10; i < 30; ++i) // journaled while the broker is away
            appendPair(i);
        QVERIFY2(m_broker->resume(&error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(unsentCount(path), qint64(0), 60000);

        CfxConsumer consumer;
        QVERIFY2(consumer.start(m_broker->url(), queue, 60), qPrintable(consumer.output()));
        QVERIFY2(consumer.finish(), qPrintable(consumer.output()));
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        QSet<QString> received;
        QString previous;
        for (int i = 0; i < consumer.messages().size(); ++i) {
            const QJsonObject envelope = envelopeAt(consumer, i);
            received << envelope.value(QStringLiteral("UniqueID")).toString();
            // In order: each clearing follows the error it clears.
            if (i % 2 == 1)
                QCOMPARE(bodyField(envelope, QStringLiteral("FaultOccurrenceId")), previous);
            previous = envelope.value(QStringLiteral("UniqueID")).toString();
        }
        QCOMPARE(received.size(), 60); // no UniqueID twice: each message arrived once
        QCOMPARE(received, journaled);
    }

    // A board is a transaction at each station: WorkStarted when the shared context names it,
    // UnitsProcessed (from a station that made joints) and WorkCompleted when it names another.
    // A change of operator, or a program naming the same board again after a restart, continues
    // the work. Sent again after a crash, each message keeps its UniqueID.
    void boardsAreTransactionsAtEachStation() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
        journal::Journal journal(path, testing::quickOptions());
        QVERIFY(testing::waitOpened(journal));
        const model::DeviceIdentity soldering = testing::sampleDevice(0);
        const model::DeviceIdentity idle = testing::sampleDevice(1);
        const auto stations = [&] { return QList<model::DeviceIdentity>{soldering, idle}; };
        const model::WorkContext none;
        const model::WorkContext first{QStringLiteral("WO-7"), QStringLiteral("SN-1"),
                                       QStringLiteral("ana")};
        model::WorkContext firstAgain = first;
        firstAgain.operatorName = QStringLiteral("ben");
        const model::WorkContext second{QStringLiteral("WO-7"), QStringLiteral("SN-2"),
                                        QStringLiteral("ben")};
        const QUuid began = journal.append(contextChange(none, first, testing::kT0), first);
        for (int i : {0, 1, 4}) // ok, slow recovery, one that never recovered
            journal.append(testing::sampleJoint(i, testing::kT0 + 1000 * (i + 1)), first);
        // Port 1 to the stand half way through the board, as the station model journals it.
        JournalEvent toStand = portEvent(JournalEvent::Kind::Status, JournalEvent::Severity::Info,
                                         1, testing::kT0 + 5000);
        toStand.details = {{QStringLiteral("from"), 0}, {QStringLiteral("to"), 1}};
        journal.append(toStand, first);
        journal.append(contextChange(first, firstAgain, testing::kT0 + 7000), firstAgain);
        journal.append(contextChange(none, firstAgain, testing::kT0 + 8000), firstAgain);
        const QUuid next =
            journal.append(contextChange(firstAgain, second, testing::kT0 + 10000), second);
        journal.append(contextChange(second, none, testing::kT0 + 20000), none);

        constexpr int kMessages = 2 + 3 + 2 + 2;
        QStringList ids;
        for (int run = 0; run < 2; ++run) {
            CfxConsumer consumer;
            QVERIFY2(
                consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), kMessages),
                qPrintable(consumer.output()));
            AmqpSender sender;
            CfxForwarder forwarder(journal, sender, handleOf, Codec::Gzip, {stations, {}, {}});
            sender.start(
                testing::quickSenderSettings(*m_broker, QStringLiteral("/exchange/amq.topic")));
            QVERIFY2(consumer.finish(), qPrintable(consumer.output()));
            QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
            QStringList names, sources, runIds;
            for (int i = 0; i < consumer.messages().size(); ++i) {
                const QJsonObject envelope = envelopeAt(consumer, i);
                names << envelope.value(QStringLiteral("MessageName")).toString().section('.', -1);
                sources << envelope.value(QStringLiteral("Source")).toString();
                runIds << envelope.value(QStringLiteral("UniqueID")).toString();
            }
            const QString a = handleOf(soldering), b = handleOf(idle);
            // A board change's messages leave station by station, in order at each.
            QCOMPARE(names, (QStringList{"WorkStarted", "WorkStarted", "UnitsProcessed",
                                         "WorkCompleted", "WorkStarted", "WorkCompleted",
                                         "WorkStarted", "WorkCompleted", "WorkCompleted"}));
            QCOMPARE(sources, (QStringList{a, b, a, a, a, b, b, a, b}));
            QTRY_COMPARE_WITH_TIMEOUT(unsentCount(path), qint64(0), 20000);

            // SN-1: one transaction, the id of the change that began it, at both stations.
            const QString transaction = began.toString(QUuid::WithoutBraces);
            for (int i : {0, 1, 3, 5})
                QCOMPARE(bodyField(envelopeAt(consumer, i), QStringLiteral("TransactionID")),
                         transaction);
            const QJsonObject processed =
                envelopeAt(consumer, 2).value(QStringLiteral("MessageBody")).toObject();
            QCOMPARE(processed.value(QStringLiteral("TransactionId")).toString(), transaction);
            QCOMPARE(processed.value(QStringLiteral("OverallResult")).toString(),
                     QStringLiteral("Failed"));
            QJsonObject secondsIn;
            for (const QJsonValue &reading : processed.value(QStringLiteral("UnitProcessData"))
                                                 .toArray()
                                                 .at(0)
                                                 .toObject()
                                                 .value(QStringLiteral("UnitProcessData"))
                                                 .toObject()
                                                 .value(QStringLiteral("Readings"))
                                                 .toArray())
                secondsIn.insert(reading.toObject().value(QStringLiteral("Name")).toString(),
                                 reading.toObject()
                                     .value(QStringLiteral("Value"))
                                     .toObject()
                                     .value(QStringLiteral("Value")));
            QCOMPARE(secondsIn.value(QStringLiteral("Port1WorkingTime")).toDouble(), 5.0);
            QCOMPARE(secondsIn.value(QStringLiteral("Port1StandTime")).toDouble(), 5.0);
            QCOMPARE(processed.value(QStringLiteral("CommonProcessData"))
                         .toObject()
                         .value(QStringLiteral("SolderPoints"))
                         .toArray()
                         .size(),
                     3);
            QCOMPARE(bodyField(envelopeAt(consumer, 3), QStringLiteral("Result")),
                     QStringLiteral("Completed"));
            QCOMPARE(bodyField(envelopeAt(consumer, 5), QStringLiteral("Result")),
                     QStringLiteral("Skipped"));
            QCOMPARE(bodyField(envelopeAt(consumer, 4), QStringLiteral("PrimaryIdentifier")),
                     QStringLiteral("SN-2"));
            QCOMPARE(bodyField(envelopeAt(consumer, 7), QStringLiteral("TransactionID")),
                     next.toString(QUuid::WithoutBraces));
            QCOMPARE(QSet<QString>(runIds.begin(), runIds.end()).size(), kMessages);
            if (run == 0) {
                ids = runIds;
                // As after a crash between the broker's acceptance and the mark: sent again.
                testing::RawDatabase db(path);
                QString error;
                QVERIFY2(db.execAll(QStringLiteral("UPDATE events SET cfx_sent = 0"), &error),
                         qPrintable(error));
            } else {
                QCOMPARE(runIds, ids);
            }
        }
    }

    // A joint under way when the board changes belongs to the board that ends (the journal
    // stamps it with the context of its start), but is journaled only once it ended: the board's
    // messages wait until the stations say so, and then carry it.
    void aBoardWaitsForTheJointsStillOpenAtItsEnd() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
        journal::Journal journal(path, testing::quickOptions());
        QVERIFY(testing::waitOpened(journal));
        const model::DeviceIdentity station = testing::sampleDevice(0);
        bool settled = true;
        qint64 askedAboutMs = 0;
        const CfxForwarder::Boards boards{[&] { return QList<model::DeviceIdentity>{station}; },
                                          {},
                                          [&](const model::DeviceIdentity &, qint64 timeMs) {
                                              askedAboutMs = timeMs;
                                              return settled;
                                          }};
        CfxConsumer consumer;
        QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), 4),
                 qPrintable(consumer.output()));
        AmqpSender sender;
        CfxForwarder forwarder(journal, sender, handleOf, Codec::Raw, boards);
        sender.start(
            testing::quickSenderSettings(*m_broker, QStringLiteral("/exchange/amq.topic")));
        journal.setContext({QString(), QStringLiteral("SN-A"), QString()});
        const qint64 namedMs = QDateTime::currentMSecsSinceEpoch(); // SN-A named by now
        QVERIFY2(consumer.waitForMessages(1), qPrintable(consumer.output()));

        settled = false; // a joint is under way
        journal.setContext({QString(), QStringLiteral("SN-B"), QString()});
        QTRY_VERIFY_WITH_TIMEOUT(askedAboutMs > 0, 10000);
        const qint64 changeMs = askedAboutMs;
        // It waits: nothing more within what a send takes on this broker (well under 500 ms).
        QTest::qWait(1000);
        QCOMPARE(consumer.messages().size(), 1);

        // Ended after the change, begun before it, while SN-A was named.
        journal.append(testing::sampleJoint(0, (namedMs + changeMs) / 2));
        settled = true;
        QVERIFY2(consumer.finish(), qPrintable(consumer.output()));
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        QStringList names;
        for (int i = 0; i < consumer.messages().size(); ++i)
            names << envelopeAt(consumer, i)
                         .value(QStringLiteral("MessageName"))
                         .toString()
                         .section('.', -1);
        QCOMPARE(names,
                 (QStringList{"WorkStarted", "UnitsProcessed", "WorkCompleted", "WorkStarted"}));
        const QJsonObject processed =
            envelopeAt(consumer, 1).value(QStringLiteral("MessageBody")).toObject();
        QCOMPARE(processed.value(QStringLiteral("CommonProcessData"))
                     .toObject()
                     .value(QStringLiteral("SolderPoints"))
                     .toArray()
                     .size(),
                 1);
        QCOMPARE(bodyField(envelopeAt(consumer, 3), QStringLiteral("PrimaryIdentifier")),
                 QStringLiteral("SN-B"));
        // The journal agrees: the joint is SN-A's.
        journal::JournalReader reader;
        QVERIFY(reader.open(path));
        journal::JointFilter onA;
        onA.boardSerial = QStringLiteral("SN-A");
        const auto onBoardA = reader.countJoints(onA);
        QVERIFY(onBoardA);
        QCOMPARE(*onBoardA, qint64(1));
    }

    // A board change on two stations, one of them still in a joint: the other's messages leave
    // at once, and so do its events after the change; the busy one's wait for its joint, and its
    // own events after the change wait behind them. At each endpoint, the journal's order.
    void eachStationsBoardLeavesOnceItsOwnJointsHaveEnded() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
        journal::Journal journal(path, testing::quickOptions());
        QVERIFY(testing::waitOpened(journal));
        const model::DeviceIdentity quick = testing::sampleDevice(1);
        const model::DeviceIdentity busy = testing::sampleDevice(0); // portEvent()'s device
        bool busySettled = true;
        int knownAsked = 0;
        const CfxForwarder::Boards boards{[&] {
                                              return QList<model::DeviceIdentity>{busy, quick};
                                          },
                                          [&] {
                                              ++knownAsked;
                                              return true;
                                          },
                                          [&](const model::DeviceIdentity &station, qint64) {
                                              return station == quick || busySettled;
                                          }};
        const model::WorkContext none;
        const model::WorkContext boardA{QString(), QStringLiteral("SN-A"), QString()};
        const model::WorkContext boardB{QString(), QStringLiteral("SN-B"), QString()};
        journal.append(contextChange(none, boardA, testing::kT0), boardA);

        CfxConsumer consumer;
        QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), 10),
                 qPrintable(consumer.output()));
        AmqpSender sender;
        CfxForwarder forwarder(journal, sender, handleOf, Codec::Raw, boards);
        sender.start(
            testing::quickSenderSettings(*m_broker, QStringLiteral("/exchange/amq.topic")));
        QVERIFY2(consumer.waitForMessages(2), qPrintable(consumer.output()));

        busySettled = false; // a joint under way at the change
        journal.append(testing::sampleJoint(0, testing::kT0 + 1000, 1, 1), boardA);
        journal.append(contextChange(boardA, boardB, testing::kT0 + 5000), boardB);
        JournalEvent quickFault = portEvent(JournalEvent::Kind::PortError,
                                            JournalEvent::Severity::Error, 2, testing::kT0 + 6000);
        quickFault.device = quick;
        journal.append(quickFault, boardB);
        journal.append(portEvent(JournalEvent::Kind::PortError, JournalEvent::Severity::Error, 1,
                                 testing::kT0 + 7000),
                       boardB);
        // The quick station's board messages and its fault, and no more while the other is busy
        // (a send takes well under 500 ms on this broker).
        QVERIFY2(consumer.waitForMessages(2 + 3 + 1), qPrintable(consumer.output()));
        QTest::qWait(1000);
        QCOMPARE(consumer.messages().size(), 2 + 3 + 1);
        QCOMPARE(unsentCount(path), qint64(2)); // the change, and the busy station's fault

        // Ended after the change, begun before it: SN-A's.
        journal.append(testing::sampleJoint(1, testing::kT0 + 4000), boardA);
        busySettled = true;
        QVERIFY2(consumer.finish(), qPrintable(consumer.output()));
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        QVERIFY(knownAsked > 0);
        QStringList atQuick, atBusy;
        for (int i = 0; i < consumer.messages().size(); ++i) {
            const QJsonObject envelope = envelopeAt(consumer, i);
            const QString name =
                envelope.value(QStringLiteral("MessageName")).toString().section('.', -1);
            const QString source = envelope.value(QStringLiteral("Source")).toString();
            (source == handleOf(quick) ? atQuick : atBusy) << name;
            if (i >= 2 && i < 6)
                QCOMPARE(source, handleOf(quick));
        }
        QCOMPARE(atQuick, (QStringList{"WorkStarted", "UnitsProcessed", "WorkCompleted",
                                       "WorkStarted", "FaultOccurred"}));
        QCOMPARE(atBusy, (QStringList{"WorkStarted", "UnitsProcessed", "WorkCompleted",
                                      "WorkStarted", "FaultOccurred"}));
        QTRY_COMPARE_WITH_TIMEOUT(unsentCount(path), qint64(0), 20000);
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TstCfxForwarder)

} // namespace tst_cfxforwarder
#include "tst_cfxforwarder.moc"
