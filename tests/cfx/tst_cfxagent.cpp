// tipscope-agent with a "cfx" section, as a plant runs it: against the test's own RabbitMQ, read
// by the independent Python consumer. Every station of the demo line says it is connected once
// the broker takes it, and says goodbye when the agent is stopped cleanly; its MQTT broker being
// absent changes nothing for CFX, and an agent that publishes CFX only ("broker": false) does the
// same without ever trying MQTT. A board named in the work context is a CFX transaction, and a
// station's changes of state are said as they happen, and requests on its queue are answered.
// tipscope-cli's monitor --cfx runs the same agent.
#include "agentprocess.h"
#include "cfxtesting.h"
#include "testmain.h"

#include "journal/journalreader.h"
#include "journal/workcontextfile.h"
#include "programrun.h"
#include "ptyfixtures.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

namespace tst_cfxagent {

using namespace tipscope;
using testing::AgentProcess;
using testing::CfxConsumer;
using testing::RabbitMqBroker;
using testing::SimProcess;

// How many joints the journal at `path` holds for the board `serial`; 0 while it cannot be read.
qint64 jointsOnBoard(journal::JournalReader &reader, const QString &path, const QString &serial) {
    journal::JointFilter filter;
    filter.boardSerial = serial;
    const auto count =
        reader.keepOpen(path) ? reader.countJoints(filter) : base::Outcome<qint64>(qint64(0));
    return count ? *count : 0;
}

class TstCfxAgent : public QObject {
    Q_OBJECT

    std::unique_ptr<RabbitMqBroker> m_broker;

    static QStringList namesOf(const CfxConsumer &consumer) { return namesIn(consumer.messages()); }
    static QStringList namesIn(const QList<QJsonObject> &messages) {
        QStringList names;
        for (const QJsonObject &m : messages)
            names << m.value(QStringLiteral("envelope"))
                         .toObject()
                         .value(QStringLiteral("MessageName"))
                         .toString();
        return names;
    }

    // No heartbeat within a test: what arrives is exactly what the test makes happen.
    QJsonObject cfxSection() const {
        return {{QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                {QStringLiteral("port"), m_broker->port()},
                {QStringLiteral("address"), QStringLiteral("/exchange/amq.topic")},
                {QStringLiteral("heartbeat_s"), 300}};
    }

    // The consumer waiting for `count` messages, and the demo line's agent publishing CFX only,
    // started once its two endpoints said they are connected.
    void startCfxOnly(CfxConsumer &consumer, int count, AgentProcess &agent) const {
        QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), count),
                 qPrintable(consumer.output()));
        agent.configure(QStringLiteral("demo"), 1, {},
                        {{QStringLiteral("cfx"), cfxSection()}, {QStringLiteral("broker"), false}});
        QString error;
        QVERIFY2(agent.start(&error), qPrintable(error));
        QVERIFY2(consumer.waitForMessages(2), qPrintable(agent.log()));
    }

private Q_SLOTS:
    void initTestCase() { testing::startCfxBroker(m_broker); }
    void cleanupTestCase() { m_broker.reset(); }

    void stationsSayHelloAndGoodbye_data() {
        QTest::addColumn<bool>("mqtt");
        QTest::newRow("beside an absent MQTT broker") << true;
        QTest::newRow("CFX only") << false;
    }

    void stationsSayHelloAndGoodbye() {
        QFETCH(bool, mqtt);
        CfxConsumer consumer;
        QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), 4),
                 qPrintable(consumer.output()));
        AgentProcess agent;
        QJsonObject extra{{QStringLiteral("cfx"), cfxSection()}};
        if (!mqtt)
            extra.insert(QStringLiteral("broker"), false);
        agent.configure(QStringLiteral("demo"), 1, {}, extra);
        QString error;
        QVERIFY2(agent.start(&error), qPrintable(error));
        QVERIFY2(consumer.waitForMessages(2), qPrintable(agent.log()));
        QCOMPARE(agent.stop(), 0);
        QVERIFY2(consumer.finish(), qPrintable(consumer.output() + agent.log()));
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        const QStringList names = namesOf(consumer);
        QCOMPARE(names, (QStringList{QStringLiteral("CFX.EndpointConnected"),
                                     QStringLiteral("CFX.EndpointConnected"),
                                     QStringLiteral("CFX.EndpointShuttingDown"),
                                     QStringLiteral("CFX.EndpointShuttingDown")}));
        QStringList handles;
        for (const QJsonObject &m : consumer.messages())
            handles << m.value(QStringLiteral("envelope"))
                           .toObject()
                           .value(QStringLiteral("Source"))
                           .toString();
        QCOMPARE(handles.at(0), handles.at(2));
        QVERIFY2(handles.at(0).startsWith(QLatin1String("JBC.")), qPrintable(handles.at(0)));
        QVERIFY2(handles.at(0).contains(QLatin1String("cell-1")), qPrintable(handles.at(0)));
        // The absent MQTT broker is tried (and said) only when there is one to try.
        QCOMPARE(agent.log().contains(QLatin1String("broker 127.0.0.1:1 ")), mqtt);
        QVERIFY2(mqtt || agent.log().contains(QLatin1String("CFX only")), qPrintable(agent.log()));
    }

    // The work context names a board while the demo station solders: the station (not the
    // feeder, which makes no joints) opens a transaction, and closes it with the joints it made
    // once the context names none.
    void aBoardNamedInTheContextIsATransaction() {
        CfxConsumer consumer;
        AgentProcess agent;
        startCfxOnly(consumer, 7, agent);
        if (QTest::currentTestFailed())
            return;
        const QString contextPath = journal::workContextPathFor(agent.journalPath());
        model::WorkContext board;
        board.boardSerial = QStringLiteral("SN-CFX-1");
        QVERIFY(journal::writeWorkContext(contextPath, board));
        QVERIFY2(consumer.waitForMessages(3), qPrintable(agent.log()));
        journal::JournalReader reader;
        const auto jointsOnTheBoard = [&] {
            return jointsOnBoard(reader, agent.journalPath(), board.boardSerial);
        };
        QTRY_VERIFY_WITH_TIMEOUT(jointsOnTheBoard() > 0, 60000);
        QVERIFY(journal::writeWorkContext(contextPath, model::WorkContext()));
        QVERIFY2(consumer.waitForMessages(5), qPrintable(agent.log()));
        QCOMPARE(agent.stop(), 0);
        QVERIFY2(consumer.finish(), qPrintable(consumer.output() + agent.log()));
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        const QStringList names = namesOf(consumer);
        QCOMPARE(names.mid(2, 3),
                 (QStringList{QStringLiteral("CFX.Production.WorkStarted"),
                              QStringLiteral("CFX.Production.Processing.UnitsProcessed"),
                              QStringLiteral("CFX.Production.WorkCompleted")}));
        const auto body = [&](int i) {
            return consumer.messages()
                .at(i)
                .value(QStringLiteral("envelope"))
                .toObject()
                .value(QStringLiteral("MessageBody"))
                .toObject();
        };
        QCOMPARE(body(2).value(QStringLiteral("PrimaryIdentifier")).toString(), board.boardSerial);
        QCOMPARE(body(3).value(QStringLiteral("TransactionId")).toString(),
                 body(2).value(QStringLiteral("TransactionID")).toString());
        QCOMPARE(body(4).value(QStringLiteral("Result")).toString(), QStringLiteral("Completed"));
        QVERIFY(!body(3)
                     .value(QStringLiteral("CommonProcessData"))
                     .toObject()
                     .value(QStringLiteral("SolderPoints"))
                     .toArray()
                     .isEmpty());
    }

    // SIGKILL while a board is open, then the agent again on the same journal, as a plant's
    // service manager restarts it: the board still ends once, with every joint the journal holds
    // for it, and no message of the spool reaches the consumer under two UniqueIDs (one sent
    // again after the kill keeps its UniqueID).
    void aKilledAgentLosesNothingAndSendsNothingTwice() {
        CfxConsumer consumer;
        AgentProcess agent;
        startCfxOnly(consumer, 1000, agent);
        if (QTest::currentTestFailed())
            return;
        const QString contextPath = journal::workContextPathFor(agent.journalPath());
        model::WorkContext board;
        board.boardSerial = QStringLiteral("SN-KILLED-1");
        QVERIFY(journal::writeWorkContext(contextPath, board));
        journal::JournalReader reader;
        const auto jointsOnTheBoard = [&] {
            return jointsOnBoard(reader, agent.journalPath(), board.boardSerial);
        };
        QTRY_VERIFY_WITH_TIMEOUT(jointsOnTheBoard() > 0, 60000);
        QVERIFY2(consumer.waitUntil([](const QList<QJsonObject> &messages) {
            return namesIn(messages).contains(QStringLiteral("CFX.Production.WorkStarted"));
        }),
                 qPrintable(agent.log()));
        agent.kill();
        const qint64 jointsOfTheKilledAgent = jointsOnTheBoard();

        // The board goes on with the next agent: it holds joints of both.
        QString error;
        QVERIFY2(agent.start(&error), qPrintable(error));
        QVERIFY2(consumer.waitUntil([](const QList<QJsonObject> &messages) {
            return namesIn(messages).count(QStringLiteral("CFX.EndpointConnected")) >= 4;
        }),
                 qPrintable(agent.log()));
        QTRY_VERIFY_WITH_TIMEOUT(jointsOnTheBoard() > jointsOfTheKilledAgent, 60000);
        QVERIFY(journal::writeWorkContext(contextPath, model::WorkContext()));
        QVERIFY2(consumer.waitUntil(
                     [](const QList<QJsonObject> &messages) {
                         return namesIn(messages).contains(
                             QStringLiteral("CFX.Production.WorkCompleted"));
                     },
                     60000),
                 qPrintable(agent.log()));
        QCOMPARE(agent.stop(), 0);
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));

        // What the spool sends (the board's messages, faults) has one UniqueID per message:
        // the same name, station and transaction, or the same fault occurrence, is one id.
        QMap<QString, QSet<QString>> idsOf;
        QJsonObject unitsProcessed;
        for (const QJsonObject &m : consumer.messages()) {
            const QJsonObject envelope = m.value(QStringLiteral("envelope")).toObject();
            const QString name = envelope.value(QStringLiteral("MessageName")).toString();
            const QJsonObject body = envelope.value(QStringLiteral("MessageBody")).toObject();
            QString what;
            if (name.startsWith(QLatin1String("CFX.Production.")))
                what = body.value(QStringLiteral("TransactionID")).toString() +
                       body.value(QStringLiteral("TransactionId")).toString();
            else if (name.startsWith(QLatin1String("CFX.ResourcePerformance.Fault")))
                what = body.value(QStringLiteral("Fault"))
                           .toObject()
                           .value(QStringLiteral("FaultOccurrenceId"))
                           .toString();
            else
                continue; // said live, once per connection
            QVERIFY2(!what.isEmpty(), qPrintable(QJsonDocument(envelope).toJson()));
            idsOf[name + QLatin1Char(' ') + envelope.value(QStringLiteral("Source")).toString() +
                  QLatin1Char(' ') + what]
                .insert(envelope.value(QStringLiteral("UniqueID")).toString());
            if (name == QLatin1String("CFX.Production.Processing.UnitsProcessed"))
                unitsProcessed = body;
        }
        for (auto it = idsOf.cbegin(); it != idsOf.cend(); ++it)
            QVERIFY2(it.value().size() == 1,
                     qPrintable(it.key() + QStringLiteral(": ") + it.value().values().join(' ')));
        const QStringList names = namesOf(consumer);
        for (const char *once :
             {"CFX.Production.WorkStarted", "CFX.Production.Processing.UnitsProcessed",
              "CFX.Production.WorkCompleted"}) {
            QStringList ids;
            for (const QString &key : idsOf.keys())
                if (key.startsWith(QLatin1String(once) + QLatin1Char(' ')))
                    ids << key;
            QVERIFY2(ids.size() == 1, qPrintable(QString::fromLatin1(once) + QLatin1Char(' ') +
                                                 names.join(QLatin1Char(' '))));
        }
        // Every joint journaled for the board, by the killed agent and by the next, is in it.
        const qint64 journaled = jointsOnTheBoard();
        QCOMPARE(unitsProcessed.value(QStringLiteral("CommonProcessData"))
                     .toObject()
                     .value(QStringLiteral("SolderPoints"))
                     .toArray()
                     .size(),
                 journaled);
    }

    // A station on a simulator steered by the test: its tool leaves the stand, then a port
    // fails. Each change is one StationStateChanged from the station's endpoint, with the SEMI
    // E10 codes as text, how long the old state lasted once the agent saw it begin.
    void aStationSaysWhenItsStateChanges() {
        SimProcess sim;
        QString error;
        const QString line = sim.start({QStringLiteral("--model"), QStringLiteral("DME"),
                                        QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")},
                                       &error);
        QVERIFY2(!line.isEmpty(), qPrintable(error));
        for (int port = 1; port <= 4; ++port)
            sim.command(QStringLiteral("status %1 1").arg(port)); // every tool in its stand
        CfxConsumer consumer;
        QVERIFY2(consumer.start(m_broker->url(),
                                QStringLiteral("/exchange/amq.topic/#.StationStateChanged"), 100),
                 qPrintable(consumer.output()));
        AgentProcess agent;
        agent.configure(line, 1, {},
                        {{QStringLiteral("cfx"), cfxSection()}, {QStringLiteral("broker"), false}});
        QVERIFY2(agent.start(&error), qPrintable(error));
        // Port 4 between sleep and hibernation changes nothing for the station, which rests
        // (one E10 state for both); once the journal holds such a change, the agent has read
        // every port. Not between the stand and sleep: the simulated station's sleep delay is 0,
        // so a port put in the stand is asleep at its next tick, and only a read in that instant
        // saw the stand (the change took 85 s to be seen under load).
        journal::JournalReader reader;
        journal::EventFilter port4;
        port4.kinds = {journal::JournalEvent::Kind::Status};
        port4.port = 4;
        QElapsedTimer toggle;
        toggle.start();
        int mode = 2;
        const auto port4Changed = [&] {
            if (toggle.elapsed() > 1500) {
                mode = 5 - mode; // 2 (sleep) and 3 (hibernation) in turn
                sim.command(QStringLiteral("status 4 %1").arg(mode));
                toggle.restart();
            }
            const auto events =
                reader.keepOpen(agent.journalPath())
                    ? reader.events(port4)
                    : base::Outcome<QList<journal::StoredEvent>>(QList<journal::StoredEvent>());
            return events && !events->isEmpty();
        };
        QTRY_VERIFY2_WITH_TIMEOUT(port4Changed(), qPrintable(agent.log()), 60000);
        const auto stateOf = [](const QJsonObject &message, const QString &field) {
            return message.value(QStringLiteral("envelope"))
                .toObject()
                .value(QStringLiteral("MessageBody"))
                .toObject()
                .value(field);
        };
        // The first message from `from` on whose new state is `state`, or -1.
        const auto firstTo = [&](const QList<QJsonObject> &messages, const QString &state,
                                 int from) {
            for (int i = from; i < messages.size(); ++i)
                if (stateOf(messages.at(i), QStringLiteral("NewState")).toString() == state)
                    return i;
            return -1;
        };
        int working = -1, failed = -1;
        sim.command(QStringLiteral("status 2 0")); // a tool out of its stand
        QVERIFY2(consumer.waitUntil([&](const QList<QJsonObject> &messages) {
            return (working = firstTo(messages, QStringLiteral("1100"), 0)) >= 0;
        }),
                 qPrintable(consumer.output() + agent.log()));
        sim.command(QStringLiteral("port-error 2 1")); // short circuit
        QVERIFY2(consumer.waitUntil([&](const QList<QJsonObject> &messages) {
            return (failed = firstTo(messages, QStringLiteral("5000"), working + 1)) >= 0;
        }),
                 qPrintable(consumer.output() + agent.log()));
        QCOMPARE(agent.stop(), 0);
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        const QList<QJsonObject> &messages = consumer.messages();
        // Before the tool left its stand the station rested (in the stand, or asleep after the
        // simulated station's sleep delay, as a real one does); every change follows the last.
        for (int i = 1; i <= failed; ++i)
            QCOMPARE(stateOf(messages.at(i), QStringLiteral("OldState")).toString(),
                     stateOf(messages.at(i - 1), QStringLiteral("NewState")).toString());
        QVERIFY(
            QStringList({QStringLiteral("2200"), QStringLiteral("2100")})
                .contains(stateOf(messages.at(working), QStringLiteral("OldState")).toString()));
        // A tool at work neither rests nor sleeps: the next change is the fault, and the agent
        // saw the work begin, so it says how long it lasted.
        QCOMPARE(failed, working + 1);
        QCOMPARE(stateOf(messages.at(failed), QStringLiteral("OldState")).toString(),
                 QStringLiteral("1100"));
        QVERIFY(stateOf(messages.at(failed), QStringLiteral("OldStateDuration")).isString());
    }

    // An MES asks the station's endpoint on the agent's request queue, as the SDK's requesters
    // do (the answers go to the requester's own queue, tied to each request): AreYouThere and
    // GetEndpointInformation are answered, anything else is "not supported".
    void requestsOnTheQueueAreAnswered() {
        const QString requests = QStringLiteral("/queue/tipscope-cfx-requests");
        CfxConsumer hello;
        QVERIFY2(hello.start(m_broker->url(),
                             QStringLiteral("/exchange/amq.topic/#.CFX.EndpointConnected"), 2),
                 qPrintable(hello.output()));
        AgentProcess agent;
        QJsonObject cfx = cfxSection();
        cfx.insert(QStringLiteral("request_address"), requests);
        agent.configure(QStringLiteral("demo"), 1, {},
                        {{QStringLiteral("cfx"), cfx}, {QStringLiteral("broker"), false}});
        QString error;
        QVERIFY2(agent.start(&error), qPrintable(error));
        QVERIFY2(hello.finish(), qPrintable(hello.output() + agent.log()));
        const QJsonObject connected = hello.messages()
                                          .at(0)
                                          .value(QStringLiteral("envelope"))
                                          .toObject()
                                          .value(QStringLiteral("MessageBody"))
                                          .toObject();
        // Where to ask is said when the endpoint connects.
        QCOMPARE(connected.value(QStringLiteral("RequestTargetAddress")).toString(), requests);
        QVERIFY(connected.value(QStringLiteral("RequestNetworkUri"))
                    .toString()
                    .startsWith(QLatin1String("amqp://")));
        const QString handle = connected.value(QStringLiteral("CFXHandle")).toString();

        CfxConsumer requester;
        QVERIFY2(
            requester.start(m_broker->url(), QStringLiteral("/queue/tipscope-cfx-answers"), 3,
                            {QStringLiteral("--request"), QStringLiteral("CFX.AreYouThereRequest"),
                             QStringLiteral("--request"),
                             QStringLiteral("CFX.GetEndpointInformationRequest"),
                             QStringLiteral("--request"),
                             QStringLiteral("CFX.Production.GetActiveRecipeRequest"),
                             QStringLiteral("--target"), handle, QStringLiteral("--send-to"),
                             requests, QStringLiteral("--gzip")}),
            qPrintable(requester.output()));
        QVERIFY2(requester.finish(), qPrintable(requester.output() + agent.log()));
        QCOMPARE(agent.stop(), 0);
        QVERIFY2(requester.complaints().isEmpty(), qPrintable(requester.complaints().join('\n')));
        QMap<QString, QJsonObject> answers;
        for (const QJsonObject &m : requester.messages()) {
            const QJsonObject envelope = m.value(QStringLiteral("envelope")).toObject();
            QCOMPARE(envelope.value(QStringLiteral("Source")).toString(), handle);
            answers.insert(envelope.value(QStringLiteral("MessageName")).toString(),
                           envelope.value(QStringLiteral("MessageBody")).toObject());
        }
        QCOMPARE(answers.keys(), (QStringList{QStringLiteral("CFX.AreYouThereResponse"),
                                              QStringLiteral("CFX.GetEndpointInformationResponse"),
                                              QStringLiteral("CFX.NotSupportedResponse")}));
        QCOMPARE(answers.value(QStringLiteral("CFX.AreYouThereResponse"))
                     .value(QStringLiteral("CFXHandle"))
                     .toString(),
                 handle);
        const QJsonObject information =
            answers.value(QStringLiteral("CFX.GetEndpointInformationResponse"))
                .value(QStringLiteral("EndpointInformation"))
                .toObject();
        QCOMPARE(information.value(QStringLiteral("CFXHandle")).toString(), handle);
        QCOMPARE(information.value(QStringLiteral("Vendor")).toString(), QStringLiteral("JBC"));
        QCOMPARE(information.value(QStringLiteral("RequestTargetAddress")).toString(), requests);
        QCOMPARE(answers.value(QStringLiteral("CFX.NotSupportedResponse"))
                     .value(QStringLiteral("RequestResult"))
                     .toObject()
                     .value(QStringLiteral("Result"))
                     .toString(),
                 QStringLiteral("Failed"));
    }

    // tipscope-cli monitor --cfx without --mqtt: the same PlantAgent, CFX only; its stations say
    // hello and goodbye, nothing tries MQTT, and having reached the broker is success.
    void theCliPublishesCfxAlone() {
        CfxConsumer consumer;
        QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), 4),
                 qPrintable(consumer.output()));
        QTemporaryDir dir;
        const testing::ProgramRun run = testing::runProgram(
            QStringLiteral("tipscope-cli"),
            {QStringLiteral("--demo"), QStringLiteral("monitor"), QStringLiteral("--cfx"),
             m_broker->url(), QStringLiteral("--duration"), QStringLiteral("4"),
             QStringLiteral("--journal"), dir.filePath(QStringLiteral("j.sqlite"))});
        QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
        QVERIFY2(run.out.contains(QLatin1String("CFX: ")), qPrintable(run.out));
        QVERIFY2(!run.out.contains(QLatin1String("live messages")), qPrintable(run.out));
        QVERIFY2(consumer.finish(), qPrintable(consumer.output() + run.err));
        QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));
        QCOMPARE(namesOf(consumer), (QStringList{QStringLiteral("CFX.EndpointConnected"),
                                                 QStringLiteral("CFX.EndpointConnected"),
                                                 QStringLiteral("CFX.EndpointShuttingDown"),
                                                 QStringLiteral("CFX.EndpointShuttingDown")}));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TstCfxAgent)

} // namespace tst_cfxagent
#include "tst_cfxagent.moc"
