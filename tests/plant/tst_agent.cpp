// tipscope-agent against a real Mosquitto broker and a simulated DME with its SFR served over TCP
// by tipscope-sim: what a plant's subscriber sees (retained info, status and counters for a late
// subscriber, live values at the configured rate, each joint once with its values), and what it
// keeps seeing through trouble: a broker down for 30 s while joints are made, a reload, a clean
// stop, kill -9, a wrong password. mosquitto_sub is the late, independent subscriber.
#include "../mqtt/mqtttesting.h"
#include "agentprocess.h"
#include "mosquittobroker.h"
#include "ptyfixtures.h"
#include "testmain.h"

#include "journal/journalreader.h"
#include "model/joints/jointdetector.h"

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryFile>
#include <QTest>
#include <csignal>

namespace tst_agent {

using namespace tipscope;
using namespace tipscope::testing;

const QString kRoot = QStringLiteral("tipscope/v1/test_site/cell-1/01-dme");
const QString kFeederRoot = QStringLiteral("tipscope/v1/test_site/cell-1/10-sfr");

struct Message {
    QString topic;
    QJsonObject payload;
    qint64 receivedMs = 0;
};

// A plant's subscriber: every message under tipscope/v1/#, with a persistent session so a broker
// that restarts (with persistence) keeps what was published while it reconnected.
class Subscriber {
public:
    explicit Subscriber(const MosquittoBroker &broker) {
        mqtt::MqttSettings settings = brokerSettings(broker, QStringLiteral("test-subscriber"));
        m_ok = subscribeAndConnect(m_client, settings, QStringLiteral("tipscope/v1/#"));
        QObject::connect(&m_client, &mqtt::MqttClient::messageReceived, &m_client,
                         [this](const QString &topic, const QByteArray &payload, bool) {
                             m_messages.append({topic, QJsonDocument::fromJson(payload).object(),
                                                QDateTime::currentMSecsSinceEpoch()});
                         });
    }
    [[nodiscard]] bool ok() const { return m_ok; }
    [[nodiscard]] QList<Message> on(const QString &topic, qsizetype from = 0) const {
        QList<Message> found;
        for (qsizetype i = from; i < m_messages.size(); ++i)
            if (m_messages.at(i).topic == topic)
                found.append(m_messages.at(i));
        return found;
    }
    [[nodiscard]] qsizetype count() const { return m_messages.size(); }
    // Waits for a message on `topic` after the first `from` that `test` accepts.
    template <typename Test>
    [[nodiscard]] std::optional<Message> waitFor(const QString &topic, Test test,
                                                 int timeoutMs = 15000, qsizetype from = 0) {
        std::optional<Message> found;
        (void)QTest::qWaitFor(
            [&] {
                for (const Message &m : on(topic, from))
                    if (test(m.payload))
                        found = m;
                return found.has_value();
            },
            timeoutMs);
        return found;
    }

private:
    mqtt::MqttClient m_client;
    QList<Message> m_messages;
    bool m_ok = false;
};

bool isOnline(const QJsonObject &status) {
    return status.value(QStringLiteral("online")).toBool();
}

class TestAgent : public QObject {
    Q_OBJECT

private:
    // Asks the simulator for a joint on port 1 until the port is at work at its temperature.
    bool makeJoint(int depth, int recoveryMs) {
        return QTest::qWaitFor(
            [&] {
                const QString reply =
                    m_sim.command(QStringLiteral("joint 1 %1 %2").arg(depth).arg(recoveryMs));
                if (reply.startsWith(QLatin1String("ok")))
                    return true;
                QTest::qWait(300);
                return false;
            },
            20000);
    }

    // Publishes a command of client tech1 (mosquitto_pub's `payload` options: -m TEXT or -f
    // FILE) and waits for the agent's result.
    std::optional<Message> commandResult(const QStringList &payload) {
        // The agent hears commands once its device is online.
        if (!m_subscriber->waitFor(kRoot + QStringLiteral("/status"), isOnline, 20000))
            return std::nullopt;
        const qsizetype from = m_subscriber->count();
        QProcess pub;
        startTool(pub, QStringLiteral("mosquitto_pub"), m_broker,
                  QStringList{QStringLiteral("-q"), QStringLiteral("1"), QStringLiteral("-t"),
                              kRoot + QStringLiteral("/cmd/apply-profile/tech1")} +
                      payload);
        if (!pub.waitForFinished(10000))
            return std::nullopt;
        return m_subscriber->waitFor(
            kRoot + QStringLiteral("/cmd/result"), [](const QJsonObject &) { return true; }, 20000,
            from);
    }

    static BrokerOptions persistent() {
        BrokerOptions options;
        options.persistence = true;
        return options;
    }

    MosquittoBroker m_broker{persistent()};
    SimProcess m_sim;
    QString m_line;
    std::unique_ptr<AgentProcess> m_agent;
    std::unique_ptr<Subscriber> m_subscriber;

private Q_SLOTS:
    void initTestCase() {
        QLoggingCategory::setFilterRules(QStringLiteral("tipscope.mqtt.debug=false"));
        TIPSCOPE_START_BROKER(m_broker);
        QString error;
        m_line = m_sim.start({QStringLiteral("--model"), QStringLiteral("DME"),
                              QStringLiteral("--feeder"), QStringLiteral("--tcp"),
                              QStringLiteral("127.0.0.1:0")},
                             &error);
        QVERIFY2(!m_line.isEmpty(), qPrintable(error));
        m_subscriber = std::make_unique<Subscriber>(m_broker);
        QVERIFY(m_subscriber->ok());
        m_agent = std::make_unique<AgentProcess>();
        m_agent->configure(
            m_line, m_broker.port(), {},
            {{QStringLiteral("live"), QJsonObject{{QStringLiteral("interval_ms"), 500}}},
             {QStringLiteral("remote_apply"), true}});
        QVERIFY2(m_agent->start(&error), qPrintable(error));
    }

    void retainedTopicsReachALateSubscriber() {
        // Once the counters were all read, the agent published them again, complete.
        const auto counters = m_subscriber->waitFor(
            kRoot + QStringLiteral("/counters"),
            [](const QJsonObject &p) {
                const QJsonArray list = p.value(QStringLiteral("counters")).toArray();
                return !list.isEmpty() &&
                       !list.first().toObject().value(QStringLiteral("h")).isNull();
            },
            30000);
        QVERIFY2(counters, qPrintable(m_agent->log()));
        QProcess sub;
        startTool(sub, QStringLiteral("mosquitto_sub"), m_broker,
                  {QStringLiteral("-v"), QStringLiteral("-C"), QStringLiteral("3"),
                   QStringLiteral("-W"), QStringLiteral("10"), QStringLiteral("-t"),
                   kRoot + QStringLiteral("/info"), QStringLiteral("-t"),
                   kRoot + QStringLiteral("/status"), QStringLiteral("-t"),
                   kRoot + QStringLiteral("/counters")});
        QVERIFY(sub.waitForFinished(15000));
        QMap<QString, QJsonObject> retained;
        for (const QByteArray &line : sub.readAllStandardOutput().split('\n')) {
            const qsizetype space = line.indexOf(' ');
            if (space > 0)
                retained.insert(QString::fromUtf8(line.left(space)),
                                QJsonDocument::fromJson(line.mid(space + 1)).object());
        }
        QCOMPARE(retained.size(), 3);
        const QJsonObject info = retained.value(kRoot + QStringLiteral("/info"));
        QCOMPARE(info.value(QStringLiteral("family")).toString(), QStringLiteral("DME"));
        QCOMPARE(info.value(QStringLiteral("address")).toString(), QStringLiteral("01"));
        QCOMPARE(info.value(QStringLiteral("line")).toString(), QStringLiteral("cell-1"));
        QVERIFY(!info.value(QStringLiteral("ports")).toArray().isEmpty());
        const QJsonObject status = retained.value(kRoot + QStringLiteral("/status"));
        QVERIFY(isOnline(status));
        QCOMPARE(status.value(QStringLiteral("agent")).toString(),
                 QStringLiteral("tipscope-agent"));
        const QJsonArray list = retained.value(kRoot + QStringLiteral("/counters"))
                                    .value(QStringLiteral("counters"))
                                    .toArray();
        QVERIFY(!list.isEmpty());
        for (const QJsonValue &c : list)
            QVERIFY2(c.toObject().contains(QStringLiteral("h")) ||
                         c.toObject().contains(QStringLiteral("count")),
                     qPrintable(QJsonDocument(c.toObject()).toJson()));
        QVERIFY(retained.value(kRoot + QStringLiteral("/info"))
                    .value(QStringLiteral("ts"))
                    .toString()
                    .endsWith(QLatin1Char('Z')));
    }

    void liveValuesComeAtTheConfiguredRate() {
        const QString topic = kRoot + QStringLiteral("/port/1/live");
        QVERIFY(m_subscriber->waitFor(topic, [](const QJsonObject &p) {
            return p.value(QStringLiteral("tip_c")).isDouble();
        }));
        const qsizetype from = m_subscriber->count();
        QTest::qWait(6000);
        const QList<Message> live = m_subscriber->on(topic, from);
        // 500 ms: 12 in 6 s, give or take the edges of the window and a slow machine.
        QVERIFY2(live.size() >= 9 && live.size() <= 14, qPrintable(QString::number(live.size())));
        for (const Message &m : live) {
            QVERIFY(m.payload.value(QStringLiteral("tip_c")).isDouble());
            QVERIFY(m.payload.value(QStringLiteral("set_c")).isDouble());
            QVERIFY(m.payload.value(QStringLiteral("power_pct")).isDouble());
            QVERIFY(!m.payload.value(QStringLiteral("status")).toString().isEmpty());
        }
        QVERIFY(!m_subscriber->on(kFeederRoot + QStringLiteral("/feeder/live"), from).isEmpty());
    }

    void aJointArrivesOnceWithItsValues() {
        const qsizetype from = m_subscriber->count();
        QVERIFY(makeJoint(60, 1200));
        const auto joint = m_subscriber->waitFor(
            kRoot + QStringLiteral("/joint"), [](const QJsonObject &) { return true; }, 20000,
            from);
        QVERIFY2(joint, qPrintable(m_agent->log()));
        const QJsonObject j = joint->payload;
        QCOMPARE(j.value(QStringLiteral("port")).toInt(), 1);
        QVERIFY2(qAbs(j.value(QStringLiteral("dip_k")).toDouble() - 60) <= 15,
                 qPrintable(QJsonDocument(j).toJson()));
        QVERIFY2(qAbs(j.value(QStringLiteral("recovery_ms")).toDouble() - 1200) <= 600,
                 qPrintable(QJsonDocument(j).toJson()));
        QVERIFY(!j.value(QStringLiteral("id")).toString().isEmpty());
        QTest::qWait(3000);
        QCOMPARE(m_subscriber->on(kRoot + QStringLiteral("/joint"), from).size(), 1);
    }

    void aProfileIsAppliedThroughTheBrokerForANamedClient() {
        const QString profile = QStringLiteral(
            R"({"request_id": "r-1", "profile": {"format": "tipscope-profile", "schema": 1,
                "family": "DME", "values": {"S21": "00200"}}})");
        const auto result = commandResult({QStringLiteral("-m"), profile});
        QVERIFY2(result, qPrintable(m_agent->log()));
        const QJsonObject r = result->payload;
        QVERIFY2(r.value(QStringLiteral("ok")).toBool(), qPrintable(QJsonDocument(r).toJson()));
        QCOMPARE(r.value(QStringLiteral("request_id")).toString(), QStringLiteral("r-1"));
        QCOMPARE(r.value(QStringLiteral("client")).toString(), QStringLiteral("tech1"));
        const QJsonArray changed = r.value(QStringLiteral("changed")).toArray();
        QCOMPARE(changed.size(), 1);
        QCOMPARE(changed.first().toObject().value(QStringLiteral("code")).toString(),
                 QStringLiteral("S21"));
        QVERIFY(changed.first().toObject().value(QStringLiteral("ok")).toBool());
        // The journal keeps who asked.
        journal::JournalReader reader;
        QVERIFY(reader.open(m_agent->journalPath()));
        QVERIFY(QTest::qWaitFor(
            [&] {
                journal::EventFilter filter;
                filter.kinds = {journal::JournalEvent::Kind::ProfileApply};
                const auto events = reader.events(filter);
                for (const journal::StoredEvent &e : events.value())
                    if (e.record.details.value(QStringLiteral("client")).toString() ==
                        QLatin1String("tech1"))
                        return true;
                return false;
            },
            10000));
    }

    // Issue 38: the wrapper was read by QJsonDocument, which kept the last of two keys, and the
    // profile re-serialised before the file's checks saw it: 450 went out where a file is refused.
    void aRemoteProfileThatMeansTwoThingsIsRefusedWithNothingWritten_data() {
        QTest::addColumn<QByteArray>("request");
        QTest::addColumn<QString>("reason");
        const QByteArray profile300 =
            R"({"format": "tipscope-profile", "schema": 1, "family": "DME", )"
            R"("values": {"S21": "00300"}})";
        QTest::newRow("a code twice")
            << QByteArray(R"({"request_id": "r-2", "profile": {"format": "tipscope-profile",
                "schema": 1, "family": "DME", "values": {"S21": "00300", "S21": "00450"}}})")
            << QStringLiteral("more than once, so which value is meant is unclear: S21");
        QTest::newRow("two profiles")
            << QByteArray(R"({"request_id": "r-2", "profile": )" + profile300 + R"(, "profile": )" +
                          QByteArray(profile300).replace("300", "450") + "}")
            << QStringLiteral("more than once, so which one is meant is unclear: profile");
        QTest::newRow("2 MB")
            << QByteArray(R"({"request_id": "r-2", "profile": )" +
                          QByteArray(profile300)
                              .replace("\"values\"", "\"comment\": \"" + QByteArray(2 << 20, 'c') +
                                                         "\", \"values\"") +
                          "}")
            << QStringLiteral("a profile is at most 1048576");
    }

    void aRemoteProfileThatMeansTwoThingsIsRefusedWithNothingWritten() {
        QFETCH(QByteArray, request);
        QFETCH(QString, reason);
        const QString before = m_sim.command(QStringLiteral("get S21"));
        QVERIFY2(before.startsWith(QLatin1String("S21=")), qPrintable(before));
        QTemporaryFile file; // mosquitto_pub -m cannot carry 2 MB in one argument
        QVERIFY(file.open() && file.write(request) == request.size() && file.flush());
        const auto result = commandResult({QStringLiteral("-f"), file.fileName()});
        QVERIFY2(result, qPrintable(m_agent->log()));
        const QJsonObject r = result->payload;
        const QString json = QString::fromUtf8(QJsonDocument(r).toJson());
        QVERIFY2(!r.value(QStringLiteral("ok")).toBool(), qPrintable(json));
        QVERIFY2(r.value(QStringLiteral("error")).toString().contains(reason), qPrintable(json));
        QVERIFY(!r.contains(QStringLiteral("changed")));
        QCOMPARE(m_sim.command(QStringLiteral("get S21")), before);
    }

    void aCommandWithoutAClientNameIsRefused() {
        const qsizetype from = m_subscriber->count();
        QProcess pub;
        startTool(pub, QStringLiteral("mosquitto_pub"), m_broker,
                  {QStringLiteral("-q"), QStringLiteral("1"), QStringLiteral("-t"),
                   kRoot + QStringLiteral("/cmd/apply-profile"), QStringLiteral("-m"),
                   QStringLiteral(R"({"format": "tipscope-profile", "schema": 1,
                                      "family": "DME", "values": {"S21": "00150"}})")});
        QVERIFY(pub.waitForFinished(10000));
        const auto result = m_subscriber->waitFor(
            kRoot + QStringLiteral("/cmd/result"), [](const QJsonObject &) { return true; }, 10000,
            from);
        QVERIFY(result);
        QVERIFY(!result->payload.value(QStringLiteral("ok")).toBool());
        QVERIFY2(result->payload.value(QStringLiteral("error"))
                     .toString()
                     .contains(QLatin1String("user name")),
                 qPrintable(QJsonDocument(result->payload).toJson()));
        QVERIFY(!result->payload.contains(QStringLiteral("changed")));
    }

    void aBrokerOutageLosesNoJoint() {
        const qint64 outageStart = QDateTime::currentMSecsSinceEpoch();
        m_broker.stop();
        // Three joints while the broker is away; the outage lasts until the journal holds them
        // (the agent keeps each before it publishes it), not for a fixed time. Each joint waits
        // until the last is kept and the tip has settled again, as the detector needs.
        journal::JournalReader reader;
        QVERIFY(reader.open(m_agent->journalPath()));
        const auto jointsSinceOutage = [&] {
            journal::JointFilter filter;
            filter.sinceMs = outageStart;
            filter.order = journal::Order::OldestFirst;
            return reader.joints(filter);
        };
        for (int made = 0; made < 3; ++made) {
            QVERIFY(makeJoint(50, 900));
            QVERIFY(
                QTest::qWaitFor([&] { return jointsSinceOutage().value().size() > made; }, 20000));
            QTest::qWait(int(model::JointDetector::kSettleMs));
        }
        QString error;
        QVERIFY2(m_broker.start(&error), qPrintable(error));
        // Every joint of the journal made since the outage began arrives, in the journal's order.
        QList<QString> expected;
        const auto kept = jointsSinceOutage();
        QVERIFY(kept.ok());
        for (const journal::StoredJoint &stored : kept.value())
            expected.append(stored.uid.toString(QUuid::WithoutBraces));
        QList<QString> arrived;
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         arrived.clear();
                         for (const Message &m : m_subscriber->on(kRoot + QStringLiteral("/joint")))
                             if (const QString id =
                                     m.payload.value(QStringLiteral("id")).toString();
                                 expected.contains(id) && !arrived.contains(id))
                                 arrived.append(id); // a duplicate (QoS 1) carries the same id
                         return arrived.size() == expected.size();
                     },
                     30000),
                 qPrintable(m_agent->log()));
        QCOMPARE(arrived, expected);
        // Then live values again.
        const qsizetype from = m_subscriber->count();
        QVERIFY(m_subscriber->waitFor(
            kRoot + QStringLiteral("/port/1/live"), [](const QJsonObject &) { return true; }, 10000,
            from));
    }

    void aReloadKeepsTheDevicesOnline() {
        // The same configuration again: new connections, but no device flashes offline.
        const qsizetype from = m_subscriber->count();
        ::kill(pid_t(m_agent->process().processId()), SIGHUP);
        QVERIFY(QTest::qWaitFor(
            [&] { return m_agent->log().contains(QLatin1String("configuration")); }, 10000));
        QVERIFY(m_subscriber->waitFor(kRoot + QStringLiteral("/status"), isOnline, 10000, from));
        QTest::qWait(2000);
        for (const Message &m : m_subscriber->on(kRoot + QStringLiteral("/status"), from))
            QVERIFY2(isOnline(m.payload), qPrintable(QJsonDocument(m.payload).toJson()));
    }

    void aReloadAppliesTheNewConfiguration() {
        m_agent->configure(m_line, m_broker.port(), {}, {{QStringLiteral("site"), "Other Site"}});
        const qsizetype from = m_subscriber->count();
        ::kill(pid_t(m_agent->process().processId()), SIGHUP);
        QVERIFY2(
            m_subscriber->waitFor(QStringLiteral("tipscope/v1/other_site/cell-1/01-dme/status"),
                                  isOnline, 15000, from),
            qPrintable(m_agent->log()));
        // A configuration that cannot be read is refused; the running one stays.
        QFile bad(m_agent->folder() + QStringLiteral("/agent.json"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(
            "{\"format\": \"tipscope-agent\", \"version\": 1, \"live\": {\"interval_ms\": 1}}");
        bad.close();
        ::kill(pid_t(m_agent->process().processId()), SIGHUP);
        QVERIFY(QTest::qWaitFor(
            [&] { return m_agent->log().contains(QLatin1String("live.interval_ms")); }, 10000));
        QVERIFY(m_agent->log().contains(QLatin1String("<3>")));
        QCOMPARE(m_agent->process().state(), QProcess::Running);
    }

    void aCleanStopSaysOffline() {
        const qsizetype from = m_subscriber->count();
        QCOMPARE(m_agent->stop(), 0);
        const auto offline = m_subscriber->waitFor(
            QStringLiteral("tipscope/v1/other_site/cell-1/01-dme/status"),
            [](const QJsonObject &p) { return !isOnline(p); }, 5000, from);
        QVERIFY2(offline, qPrintable(m_agent->log()));
        QVERIFY(offline->payload.contains(QStringLiteral("ts")));
    }

    void killNineTurnsTheRetainedStatusOffline() {
        m_agent = std::make_unique<AgentProcess>();
        m_agent->configure(m_line, m_broker.port());
        QString error;
        const qsizetype before = m_subscriber->count();
        QVERIFY2(m_agent->start(&error), qPrintable(error));
        QVERIFY(m_subscriber->waitFor(kRoot + QStringLiteral("/status"), isOnline, 20000, before));
        // This agent's configuration leaves remote apply off: a command is refused, saying so.
        QProcess pub;
        startTool(pub, QStringLiteral("mosquitto_pub"), m_broker,
                  {QStringLiteral("-q"), QStringLiteral("1"), QStringLiteral("-t"),
                   kRoot + QStringLiteral("/cmd/apply-profile/tech1"), QStringLiteral("-m"),
                   QStringLiteral(R"({"format": "tipscope-profile", "schema": 1,
                                      "family": "DME", "values": {"S21": "00150"}})")});
        QVERIFY(pub.waitForFinished(10000));
        const auto refused = m_subscriber->waitFor(
            kRoot + QStringLiteral("/cmd/result"),
            [](const QJsonObject &r) { return !r.value(QStringLiteral("ok")).toBool(); }, 10000,
            before);
        QVERIFY(refused);
        QVERIFY(refused->payload.value(QStringLiteral("error"))
                    .toString()
                    .contains(QLatin1String("off")));
        const qsizetype from = m_subscriber->count();
        QElapsedTimer sinceKill;
        sinceKill.start();
        m_agent->kill();
        for (const QString &root : {kRoot, kFeederRoot})
            QVERIFY2(m_subscriber->waitFor(
                         root + QStringLiteral("/status"),
                         [](const QJsonObject &p) { return !isOnline(p); }, 7500, from),
                     qPrintable(root));
        QVERIFY(sinceKill.elapsed() <= 7500); // 1.5 x the keep-alive of 5 s
        // Retained: a subscriber that comes now reads offline.
        QProcess sub;
        startTool(sub, QStringLiteral("mosquitto_sub"), m_broker,
                  {QStringLiteral("-C"), QStringLiteral("1"), QStringLiteral("-W"),
                   QStringLiteral("5"), QStringLiteral("-t"), kRoot + QStringLiteral("/status")});
        QVERIFY(sub.waitForFinished(10000));
        const QJsonObject will = QJsonDocument::fromJson(sub.readAllStandardOutput()).object();
        QVERIFY(!isOnline(will));
        QVERIFY(will.value(QStringLiteral("will")).toBool()); // its time is not when it went
    }

    void aWrongPasswordIsSaidAndPollingGoesOn() {
        m_agent.reset(); // the simulator serves one client at a time
        BrokerOptions options;
        options.users.insert(QStringLiteral("agent"), QStringLiteral("right"));
        MosquittoBroker guarded(options);
        TIPSCOPE_START_BROKER(guarded);
        AgentProcess agent;
        QFile secret(agent.folder() + QStringLiteral("/password"));
        QVERIFY(secret.open(QIODevice::WriteOnly));
        secret.write("wrong-secret\n");
        secret.close();
        agent.configure(m_line, guarded.port(),
                        {{QStringLiteral("username"), QStringLiteral("agent")},
                         {QStringLiteral("password_file"), QStringLiteral("password")}});
        QString error;
        QVERIFY2(agent.start(&error), qPrintable(error));
        QVERIFY2(QTest::qWaitFor(
                     [&] { return agent.log().contains(QLatin1String("refused the connection")); },
                     15000),
                 qPrintable(agent.log()));
        // Polling goes on: joints are found and journaled while the broker refuses the agent. The
        // first may come before the agent has seen the tip settle (no joint without a baseline).
        journal::JournalReader reader;
        const auto journaled = [&] {
            if (!reader.isOpen() && !reader.open(agent.journalPath()))
                return false;
            const auto joints = reader.countJoints({});
            return joints && joints.value() >= 1;
        };
        for (int attempt = 0; attempt < 3 && !journaled(); ++attempt) {
            QVERIFY(makeJoint(40, 800));
            (void)QTest::qWaitFor(journaled, 8000);
        }
        QVERIFY2(journaled(), qPrintable(agent.log()));
        QVERIFY(!agent.log().contains(QLatin1String("wrong-secret")));
        QCOMPARE(agent.stop(), 0);
    }

    // Issue 38: such an agent published live values, lost every joint and exited 0 on SIGTERM.
    void anAgentWhoseJournalCannotBeUsedStopsSayingWhy_data() {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("reason");
        QTest::newRow("not SQLite")
            << QStringLiteral("text") << QStringLiteral("is damaged or is not a journal");
        QTest::newRow("a newer schema")
            << QStringLiteral("newer") << QStringLiteral("written by a newer TipScope");
        QTest::newRow("a folder where the file should be")
            << QStringLiteral("folder") << QStringLiteral("cannot be written");
    }

    void anAgentWhoseJournalCannotBeUsedStopsSayingWhy() {
        QFETCH(QString, kind);
        QFETCH(QString, reason);
        AgentProcess agent;
        agent.configure(QStringLiteral("demo"), m_broker.port());
        const QString path = agent.journalPath();
        if (kind == QLatin1String("folder")) {
            QVERIFY(QDir().mkpath(path));
        } else if (kind == QLatin1String("text")) {
            QFile text(path);
            QVERIFY(text.open(QIODevice::WriteOnly) && text.write(QByteArray(4096, 'j')) == 4096);
        } else {
            {
                QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), kind);
                db.setDatabaseName(path);
                QVERIFY(db.open());
                QVERIFY(db.exec(QStringLiteral("PRAGMA user_version = 99")).lastError().type() ==
                        QSqlError::NoError);
                db.close();
            }
            QSqlDatabase::removeDatabase(kind);
        }
        QString error;
        QVERIFY2(agent.start(&error), qPrintable(error));
        QVERIFY2(agent.process().waitForFinished(30000), qPrintable(agent.log()));
        QCOMPARE(agent.process().exitStatus(), QProcess::NormalExit);
        QVERIFY2(agent.process().exitCode() == 3, qPrintable(agent.log()));
        QVERIFY2(agent.log().contains(reason), qPrintable(agent.log()));
        QVERIFY2(agent.log().contains(QLatin1String("<3>")), qPrintable(agent.log())); // critical
        QVERIFY2(agent.log().contains(QLatin1String("the agent stops")), qPrintable(agent.log()));
    }

    void cleanupTestCase() {
        m_agent.reset();
        m_subscriber.reset();
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestAgent)

} // namespace tst_agent
#include "tst_agent.moc"
