// tipscope-agent with a "cfx" section, as a plant runs it: against the test's own RabbitMQ, read
// by the independent Python consumer. Every station of the demo line says it is connected once
// the broker takes it, and says goodbye when the agent is stopped cleanly; its MQTT broker being
// absent changes nothing for CFX, and an agent that publishes CFX only ("broker": false) does the
// same without ever trying MQTT. A board named in the work context is a CFX transaction.
#include "agentprocess.h"
#include "cfxtesting.h"

#include "journal/journalreader.h"
#include "journal/workcontextfile.h"

#include <QJsonObject>
#include <QTest>

using namespace tipscope;
using testing::AgentProcess;
using testing::CfxConsumer;
using testing::RabbitMqBroker;

class TstCfxAgent : public QObject {
    Q_OBJECT

    std::unique_ptr<RabbitMqBroker> m_broker;

    static QStringList namesOf(const CfxConsumer &consumer) {
        QStringList names;
        for (const QJsonObject &m : consumer.messages())
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
        QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), 7),
                 qPrintable(consumer.output()));
        AgentProcess agent;
        agent.configure(QStringLiteral("demo"), 1, {},
                        {{QStringLiteral("cfx"), cfxSection()}, {QStringLiteral("broker"), false}});
        QString error;
        QVERIFY2(agent.start(&error), qPrintable(error));
        QVERIFY2(consumer.waitForMessages(2), qPrintable(agent.log()));
        const QString contextPath = journal::workContextPathFor(agent.journalPath());
        model::WorkContext board;
        board.boardSerial = QStringLiteral("SN-CFX-1");
        QVERIFY(journal::writeWorkContext(contextPath, board));
        QVERIFY2(consumer.waitForMessages(3), qPrintable(agent.log()));
        journal::JournalReader reader;
        journal::JointFilter filter;
        filter.boardSerial = board.boardSerial;
        const auto jointsOnTheBoard = [&] {
            const auto count = reader.keepOpen(agent.journalPath())
                                   ? reader.countJoints(filter)
                                   : protocol::Outcome<qint64>(qint64(0));
            return count ? *count : 0;
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
};

QTEST_GUILESS_MAIN(TstCfxAgent)
#include "tst_cfxagent.moc"
