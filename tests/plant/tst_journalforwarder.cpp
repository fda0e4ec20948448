// JournalForwarder, store and forward, against a broker made of a QTcpServer that speaks the MQTT
// 3.1.1 packets a publisher needs (no broker process) and counts what it is sent: every joint of
// a real journal reaches it, none is marked sent before the broker acknowledged it, and across a
// dropped connection and a restart of the forwarder and its client nothing is lost; what comes
// twice (QoS 1 is at least once) comes with its record's id, and only what was not acknowledged
// comes again.
#include "journal/journal.h"
#include "journal/journalreader.h"
#include "journalfixture.h"
#include "mqtt/mqttclient.h"
#include "plant/journalforwarder.h"
#include "testmain.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

namespace tst_journalforwarder {

using namespace tipscope;

// One PUBLISH as the broker received it.
struct Received {
    QString recordId;       // the payload's "id"
    bool duplicate = false; // the DUP flag: sent again after a lost connection
    bool acknowledged = false;
};

// The broker: takes CONNECTs, PUBLISHes of QoS 1 and pings, one connection at a time. It
// acknowledges the next `acknowledging` PUBLISHes (all when negative), then nothing (a broker too
// busy, or a connection about to drop).
class FakeBroker : public QObject {
public:
    FakeBroker() {
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *s = m_server.nextPendingConnection()) {
                if (m_peer)
                    m_peer->abort();
                m_peer.reset(s);
                m_buffer.clear();
                ++connections;
                connect(s, &QTcpSocket::readyRead, this, [this] { take(); });
            }
        });
    }
    bool listen() { return m_server.listen(QHostAddress::LocalHost); }
    [[nodiscard]] quint16 port() const { return m_server.serverPort(); }
    void drop() {
        if (m_peer)
            m_peer->abort();
    }
    [[nodiscard]] QSet<QString> distinct() const {
        QSet<QString> ids;
        for (const Received &r : received)
            ids.insert(r.recordId);
        return ids;
    }
    [[nodiscard]] int acknowledgedCount() const {
        return int(std::count_if(received.cbegin(), received.cend(),
                                 [](const Received &r) { return r.acknowledged; }));
    }

    int acknowledging = -1;
    int connections = 0;
    QList<Received> received;

private:
    void send(const QByteArray &bytes) {
        if (m_peer)
            m_peer->write(bytes);
    }
    // Whole packets from what came: a fixed header, a remaining length of up to four bytes.
    void take() {
        m_buffer += m_peer->readAll();
        for (;;) {
            int length = 0, shift = 0, at = 1;
            for (; at < m_buffer.size() && at <= 4; ++at, shift += 7) {
                length |= (quint8(m_buffer[at]) & 0x7f) << shift;
                if (!(quint8(m_buffer[at]) & 0x80))
                    break;
            }
            if (at >= m_buffer.size() || m_buffer.size() < at + 1 + length)
                return;
            const quint8 first = quint8(m_buffer[0]);
            const QByteArray body = m_buffer.mid(at + 1, length);
            m_buffer.remove(0, at + 1 + length);
            handle(first, body);
        }
    }
    void handle(quint8 first, const QByteArray &body) {
        switch (first >> 4) {
        case 1: // CONNECT
            send(QByteArray::fromHex("20020000"));
            break;
        case 3: { // PUBLISH, QoS 1
            const int topicLength = (quint8(body[0]) << 8) | quint8(body[1]);
            const QByteArray packetId = body.mid(2 + topicLength, 2);
            const QByteArray payload = body.mid(2 + topicLength + 2);
            Received r;
            r.recordId =
                QJsonDocument::fromJson(payload).object().value(QStringLiteral("id")).toString();
            r.duplicate = (first & 0x08) != 0;
            r.acknowledged = acknowledging != 0;
            if (acknowledging > 0)
                --acknowledging;
            received.append(r);
            if (r.acknowledged)
                send(QByteArray::fromHex("4002") + packetId);
            break;
        }
        case 12: // PINGREQ
            send(QByteArray::fromHex("d000"));
            break;
        case 14: // DISCONNECT
            m_peer->disconnectFromHost();
            break;
        default:
            break;
        }
    }

    QTcpServer m_server;
    std::unique_ptr<QTcpSocket> m_peer;
    QByteArray m_buffer;
};

// A client and its forwarder, as the agent has them.
struct Publisher {
    Publisher(journal::Journal &journal, quint16 port) {
        mqtt::MqttSettings settings;
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = port;
        settings.clientId = QStringLiteral("forwarder-test");
        settings.retryMinMs = 100;
        settings.retryMaxMs = 200;
        client.setSettings(settings);
        forwarder = std::make_unique<plant::JournalForwarder>(
            journal, client, [](const model::DeviceIdentity &) {
                return plant::DevicePlace{QStringLiteral("line-1"), QString(),
                                          QStringLiteral("tipscope/v1/test"), QString()};
            });
        client.start();
    }
    mqtt::MqttClient client;
    std::unique_ptr<plant::JournalForwarder> forwarder;
};

qsizetype unsentJoints(const QString &path) {
    journal::JournalReader reader;
    if (!reader.open(path))
        return -1;
    const auto unsent = reader.unsentJoints(0, 1000);
    return unsent ? unsent->size() : -1;
}

class TstJournalForwarder : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void nothingIsLostAcrossADroppedConnectionAndARestart();
};

void TstJournalForwarder::nothingIsLostAcrossADroppedConnectionAndARestart() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    journal::Journal journal(path, testing::quickOptions());
    QVERIFY(testing::waitOpened(journal));
    constexpr int kFirst = 30, kLater = 12;
    for (int i = 0; i < kFirst; ++i)
        journal.append(testing::sampleJoint(i, testing::kT0 + i * 1000));
    QVERIFY(journal.flush());
    FakeBroker broker;
    QVERIFY(broker.listen());

    // The first ten acknowledged, then none: those sent after them stay unsent in the journal.
    broker.acknowledging = 10;
    auto publisher = std::make_unique<Publisher>(journal, broker.port());
    QVERIFY(QTest::qWaitFor([&] { return broker.received.size() >= kFirst; }, 10000));
    QVERIFY(QTest::qWaitFor(
        [&] {
            return journal.flush() && unsentJoints(path) == kFirst - broker.acknowledgedCount();
        },
        10000));
    QCOMPARE(broker.acknowledgedCount(), 10);

    // The connection drops; the client connects again and sends what was not acknowledged.
    broker.acknowledging = -1;
    broker.drop();
    QVERIFY(QTest::qWaitFor([&] { return broker.connections == 2; }, 10000));
    QVERIFY(QTest::qWaitFor([&] { return journal.flush() && unsentJoints(path) == 0; }, 10000));
    QCOMPARE(broker.distinct().size(), kFirst);

    // Later joints, sent and not acknowledged when the agent stops; a new one sends them.
    for (int i = kFirst; i < kFirst + kLater; ++i)
        journal.append(testing::sampleJoint(i, testing::kT0 + i * 1000));
    QVERIFY(journal.flush());
    broker.acknowledging = 0;
    const qsizetype before = broker.received.size();
    QVERIFY(QTest::qWaitFor([&] { return broker.received.size() >= before + kLater; }, 10000));
    publisher.reset(); // stopped without its acknowledgements, as a killed agent would be
    broker.acknowledging = -1;
    broker.drop();
    QCOMPARE(unsentJoints(path), qsizetype(kLater));
    publisher = std::make_unique<Publisher>(journal, broker.port());
    QVERIFY(QTest::qWaitFor([&] { return journal.flush() && unsentJoints(path) == 0; }, 10000));

    // Every record arrived; each one that came again was one not acknowledged before.
    QCOMPARE(broker.distinct().size(), kFirst + kLater);
    QHash<QString, int> acknowledgedTimes;
    for (const Received &r : std::as_const(broker.received))
        acknowledgedTimes[r.recordId] += r.acknowledged ? 1 : 0;
    for (auto it = acknowledgedTimes.cbegin(); it != acknowledgedTimes.cend(); ++it)
        QVERIFY2(it.value() == 1,
                 qPrintable(it.key() + QStringLiteral(" acknowledged %1 times").arg(it.value())));
    QVERIFY(broker.received.size() > kFirst + kLater); // some came twice, none is missing
}

TIPSCOPE_TEST_GUILESS_MAIN(TstJournalForwarder)

} // namespace tst_journalforwarder

#include "tst_journalforwarder.moc"
