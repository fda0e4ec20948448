// tipscope-agent with a "cfx" section, as a plant runs it: against the test's own RabbitMQ, read
// by the independent Python consumer. Every station of the demo line says it is connected once
// the broker takes it, and says goodbye when the agent is stopped cleanly; its MQTT broker being
// absent changes nothing for CFX, and an agent that publishes CFX only ("broker": false) does the
// same without ever trying MQTT.
#include "agentprocess.h"
#include "cfxtesting.h"

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
        // No heartbeat within the test: what arrives is exactly the hellos and the goodbyes.
        const QJsonObject cfx{{QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                              {QStringLiteral("port"), m_broker->port()},
                              {QStringLiteral("address"), QStringLiteral("/exchange/amq.topic")},
                              {QStringLiteral("heartbeat_s"), 300}};
        QJsonObject extra{{QStringLiteral("cfx"), cfx}};
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
};

QTEST_GUILESS_MAIN(TstCfxAgent)
#include "tst_cfxagent.moc"
