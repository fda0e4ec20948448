// CfxPublisher against a real RabbitMQ, read by the independent Python consumer: an endpoint says
// it is connected, then beats with the faults active at its station, as the journal raised them
// and did not clear them; the journal's faults leave through the forwarder, each once.
#include "cfx/cfxpublisher.h"
#include "cfxtesting.h"
#include "journalfixture.h"
#include "testmain.h"

#include "journal/journal.h"

#include <QJsonArray>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_cfxpublisher {

using namespace tipscope;
using namespace tipscope::cfx;
using journal::JournalEvent;
using testing::CfxConsumer;
using testing::RabbitMqBroker;

namespace {
QString handleOf(const model::DeviceIdentity &device) {
    return endpointHandle(QStringLiteral("JBC"), device.model,
                          QStringLiteral("%1-%2")
                              .arg(device.line.section(QLatin1Char('/'), -1))
                              .arg(device.address.value_or(0)));
}

QList<QJsonObject> named(const CfxConsumer &consumer, const QString &name) {
    QList<QJsonObject> out;
    for (const QJsonObject &m : consumer.messages()) {
        const QJsonObject envelope = m.value(QStringLiteral("envelope")).toObject();
        if (envelope.value(QStringLiteral("MessageName")).toString() == name)
            out.append(envelope);
    }
    return out;
}
} // namespace

class TestCfxPublisher : public QObject {
    Q_OBJECT
    std::unique_ptr<RabbitMqBroker> m_broker;

private Q_SLOTS:
    void initTestCase() { testing::startCfxBroker(m_broker); }
    void cleanupTestCase() { m_broker.reset(); }

    void aHeartbeatNamesTheFaultsActiveAtItsStation();
};

void TestCfxPublisher::aHeartbeatNamesTheFaultsActiveAtItsStation() {
    QTemporaryDir dir;
    journal::Journal journal(dir.filePath(QStringLiteral("journal.sqlite")),
                             testing::quickOptions());
    QVERIFY(testing::waitOpened(journal));
    const QUuid open = journal.append(testing::portEvent(
        JournalEvent::Kind::PortError, JournalEvent::Severity::Error, 2, testing::kT0));
    journal.append(testing::portEvent(JournalEvent::Kind::PortError, JournalEvent::Severity::Error,
                                      3, testing::kT0 + 10));
    journal.append(testing::portEvent(JournalEvent::Kind::PortError, JournalEvent::Severity::Info,
                                      3, testing::kT0 + 20));
    QVERIFY(journal.flush());

    const model::DeviceIdentity station = testing::sampleDevice(0);
    const QString handle = handleOf(station);
    // EndpointConnected, the three faults' messages and a first heartbeat.
    CfxConsumer consumer;
    QVERIFY2(consumer.start(m_broker->url(), QStringLiteral("/exchange/amq.topic/#"), 5),
             qPrintable(consumer.output()));
    CfxSettings settings;
    settings.host = QStringLiteral("127.0.0.1");
    settings.port = m_broker->port();
    settings.heartbeatS = 1;
    settings.retryMaxS = 1;
    CfxPublisher publisher(journal, settings, handleOf, [&] {
        return QList<EndpointIdentity>{{handle, QStringLiteral("JBC"), station.model,
                                        QStringLiteral("line 1"), QStringLiteral("1.0")}};
    });
    publisher.start();
    QVERIFY2(consumer.finish(), qPrintable(consumer.output()));
    QVERIFY2(consumer.complaints().isEmpty(), qPrintable(consumer.complaints().join('\n')));

    QCOMPARE(named(consumer, QStringLiteral("CFX.EndpointConnected")).size(), 1);
    QCOMPARE(named(consumer, QStringLiteral("CFX.ResourcePerformance.FaultOccurred")).size(), 2);
    QCOMPARE(named(consumer, QStringLiteral("CFX.ResourcePerformance.FaultCleared")).size(), 1);
    const QList<QJsonObject> beats = named(consumer, QStringLiteral("CFX.Heartbeat"));
    QCOMPARE(beats.size(), 1);
    const QJsonObject body = beats.first().value(QStringLiteral("MessageBody")).toObject();
    QCOMPARE(body.value(QStringLiteral("CFXHandle")).toString(), handle);
    const QJsonArray active = body.value(QStringLiteral("ActiveFaults")).toArray();
    QCOMPARE(active.size(), 1);
    QCOMPARE(active.first().toObject().value(QStringLiteral("FaultOccurrenceId")).toString(),
             open.toString(QUuid::WithoutBraces));

    QSignalSpy stopped(&publisher, &CfxPublisher::stopped);
    publisher.stop();
    QVERIFY(stopped.count() == 1 || stopped.wait(5000));
}

TIPSCOPE_TEST_MAIN(TestCfxPublisher)

} // namespace tst_cfxpublisher
#include "tst_cfxpublisher.moc"
