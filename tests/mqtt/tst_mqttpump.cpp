// MqttPump driving a libmosquitto client from the event loop, against a broker made of a
// QTcpServer that speaks the few MQTT 3.1.1 packets each case needs (no broker process): the
// CONNECT written and the CONNACK read through the socket notifiers; a quiet pump unwatched
// when idle, reading on its tick what came meanwhile, watched again as soon as it sends; and a
// broker that hangs up let go of.
#include "mqtt/mqttpump.h"
#include "mqtt/mqttsetup.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <memory>
#include <mosquitto.h>

namespace tst_mqttpump {

using namespace tipscope::mqtt;

// What the client's callbacks saw.
struct Seen {
    int connacks = 0;
    int connackCode = -1;
    QList<QByteArray> payloads;
};

// The broker's side of one connection: takes the CONNECT, answers CONNACK.
class FakeBroker {
public:
    bool listen() { return m_server.listen(QHostAddress::LocalHost); }
    [[nodiscard]] quint16 port() const { return m_server.serverPort(); }
    // Waits for the client's connection and its CONNECT (packet type 1), then accepts it.
    bool acceptConnect() {
        if (!QTest::qWaitFor([&] { return m_server.hasPendingConnections(); }, 5000))
            return false;
        m_peer.reset(m_server.nextPendingConnection());
        if (!QTest::qWaitFor([&] { return m_peer->bytesAvailable() > 0; }, 5000) ||
            (quint8(m_peer->readAll().at(0)) >> 4) != 1)
            return false;
        send(QByteArray::fromHex("20020000")); // CONNACK, accepted
        return true;
    }
    // A QoS 0 PUBLISH of `payload` on "t".
    void publish(const QByteArray &payload) {
        QByteArray packet = QByteArray::fromHex("30");
        packet.append(char(2 + 1 + payload.size()));
        packet.append(QByteArray::fromHex("000174")).append(payload);
        send(packet);
    }
    void hangUp() { m_peer->abort(); }
    [[nodiscard]] QByteArray received() { return m_peer->readAll(); }

private:
    void send(const QByteArray &bytes) {
        m_peer->write(bytes);
        m_peer->flush();
    }
    QTcpServer m_server;
    std::unique_ptr<QTcpSocket> m_peer;
};

class TstMqttPump : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void theConnectIsWrittenAndItsAnswerReadThroughTheLoop();
    void aQuietPumpReadsOnItsTickWhatCameWhileItWasUnwatched();
    void aBrokerThatHangsUpIsLetGo();

private:
    // Connects a new client through `m_pump` to the fake broker; false if it did not connect.
    bool connectThroughPump();

    std::unique_ptr<FakeBroker> m_broker;
    MosquittoHandle m_client;
    std::unique_ptr<MqttPump> m_pump;
    Seen m_seen;
    QList<int> m_serviced; // return codes of the pump's calls
};

void TstMqttPump::init() {
    m_seen = {};
    m_serviced.clear();
    m_broker = std::make_unique<FakeBroker>();
    QVERIFY(m_broker->listen());
    MqttSettings settings;
    settings.clientId = QStringLiteral("pump");
    settings.cleanSession = true;
    auto created = createMosquitto(settings, &m_seen);
    QVERIFY2(created, qPrintable(created ? QString() : created.error()));
    m_client = std::move(created).value();
    mosquitto_connect_callback_set(m_client.get(), [](mosquitto *, void *data, int code) {
        auto *seen = static_cast<Seen *>(data);
        ++seen->connacks;
        seen->connackCode = code;
    });
    mosquitto_message_callback_set(
        m_client.get(), [](mosquitto *, void *data, const mosquitto_message *message) {
            static_cast<Seen *>(data)->payloads.append(
                QByteArray(static_cast<const char *>(message->payload), message->payloadlen));
        });
    m_pump = std::make_unique<MqttPump>();
    // As MqttClient does: after each call of the pump's, follow the socket.
    connect(m_pump.get(), &MqttPump::serviced, this, [this](int rc, int) {
        m_serviced.append(rc);
        m_pump->sync();
    });
}

void TstMqttPump::cleanup() {
    m_pump.reset();
    m_client.reset();
    m_broker.reset();
}

bool TstMqttPump::connectThroughPump() {
    if (mosquitto_connect_async(m_client.get(), "127.0.0.1", m_broker->port(), 60) !=
        MOSQ_ERR_SUCCESS)
        return false;
    m_pump->attach(m_client.get());
    return m_broker->acceptConnect() &&
           QTest::qWaitFor([&] { return m_seen.connacks == 1; }, 5000) && m_seen.connackCode == 0;
}

void TstMqttPump::theConnectIsWrittenAndItsAnswerReadThroughTheLoop() {
    QVERIFY(connectThroughPump());
    QVERIFY(m_pump->watching());
    QVERIFY(m_pump->watchesReads()); // not quiet: always watched
    m_broker->publish("now");
    QVERIFY(QTest::qWaitFor([&] { return m_seen.payloads.size() == 1; }, 5000));
    QCOMPARE(m_seen.payloads.first(), QByteArray("now"));
    QVERIFY(!m_serviced.contains(MOSQ_ERR_CONN_LOST));
}

void TstMqttPump::aQuietPumpReadsOnItsTickWhatCameWhileItWasUnwatched() {
    m_pump->setQuiet(true);
    QVERIFY(connectThroughPump());
    QVERIFY(m_pump->watchesReads()); // it has just sent its CONNECT
    QVERIFY(QTest::qWaitFor([&] { return !m_pump->watchesReads(); },
                            (MqttPump::kQuietAfterTicks + 2) * 1000));
    m_broker->publish("while unwatched");
    QVERIFY(QTest::qWaitFor([&] { return m_seen.payloads.size() == 1; }, 2500));
    QCOMPARE(m_seen.payloads.first(), QByteArray("while unwatched"));
    QVERIFY(!m_pump->watchesReads()); // reading on the tick woke nothing

    // Something sent (a PUBLISH): the broker's answer is on its way, the socket watched again.
    QCOMPARE(mosquitto_publish(m_client.get(), nullptr, "t", 2, "up", 1, false), MOSQ_ERR_SUCCESS);
    m_pump->sync();
    QVERIFY(m_pump->watchesReads());
    QVERIFY(QTest::qWaitFor([&] { return m_broker->received().size() > 0; }, 5000));
}

void TstMqttPump::aBrokerThatHangsUpIsLetGo() {
    m_pump->setQuiet(true);
    QVERIFY(connectThroughPump());
    QVERIFY(QTest::qWaitFor([&] { return !m_pump->watchesReads(); },
                            (MqttPump::kQuietAfterTicks + 2) * 1000));
    m_broker->hangUp();
    // Unwatched, the hang-up is found on the next tick: the client loses its connection and
    // the pump its socket.
    QVERIFY(QTest::qWaitFor([&] { return !m_pump->watching(); }, 2500));
    QVERIFY(m_serviced.contains(MOSQ_ERR_CONN_LOST) || m_serviced.contains(MOSQ_ERR_NO_CONN));
}

TIPSCOPE_TEST_GUILESS_MAIN(TstMqttPump)

} // namespace tst_mqttpump

#include "tst_mqttpump.moc"
