#include "mqttbench.h"

#include "benchsupport.h"
#include "mosquittobroker.h"
#include "mqtt/mqttclient.h"

#include <QCommandLineParser>
#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QTimer>

namespace tipscope::bench {

namespace {

using mqtt::MqttClient;

struct Options {
    int idleSeconds = 10;
    int messages = 20000;
};

// Voluntary context switches of this process so far: each is a wait that ended, a wake-up.
qint64 contextSwitches() {
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return 0;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("voluntary_ctxt_switches:"))
            return line.mid(line.indexOf(':') + 1).trimmed().toLongLong();
    }
    return 0;
}

bool connectClient(MqttClient &client, const testing::MosquittoBroker &broker, const QString &id) {
    mqtt::MqttSettings settings;
    settings.host = QStringLiteral("127.0.0.1");
    settings.port = broker.port();
    settings.clientId = id;
    settings.maxPendingMessages = 1000000;
    client.setSettings(settings);
    client.start();
    return runUntil([&] { return client.state() == MqttClient::State::Connected; }, 10000);
}

void measureIdle(int seconds) {
    const qint64 cpuBefore = selfCpuUs();
    const qint64 switchesBefore = contextSwitches();
    QEventLoop idle;
    QTimer::singleShot(seconds * 1000, &idle, &QEventLoop::quit);
    idle.exec();
    const double cpuPct = 100.0 * double(selfCpuUs() - cpuBefore) / (seconds * 1e6);
    printFigure(QStringLiteral("mqtt.idle_cpu"), cpuPct, QStringLiteral("%"), 3);
    printFigure(QStringLiteral("mqtt.idle_wakeups"),
                double(contextSwitches() - switchesBefore) / seconds, QStringLiteral("/s"));
}

void measureQos1(MqttClient &publisher, MqttClient &subscriber, int messages) {
    int acknowledged = 0;
    int received = 0;
    QObject context;
    QObject::connect(&publisher, &MqttClient::published, &context, [&] { ++acknowledged; });
    QObject::connect(&subscriber, &MqttClient::messageReceived, &context, [&] { ++received; });
    const QByteArray payload(200, 'j'); // about a joint record in JSON
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < messages; ++i) {
        if (!publisher.publish(QStringLiteral("tipscope/bench/joint"), payload, 1, false).ok())
            printError(QStringLiteral("a publish was refused"));
    }
    const double publishS = clock.nsecsElapsed() / 1e9;
    if (!runUntil([&] { return acknowledged == messages; }, 120000))
        printError(QStringLiteral("only %1 of %2 acknowledged").arg(acknowledged).arg(messages));
    const double ackedS = clock.nsecsElapsed() / 1e9;
    if (!runUntil([&] { return received == messages; }, 120000))
        printError(QStringLiteral("only %1 of %2 received").arg(received).arg(messages));
    const double receivedS = clock.nsecsElapsed() / 1e9;
    printFigure(QStringLiteral("mqtt.qos1_publish_calls"), messages / publishS,
                QStringLiteral("msg/s"), 0);
    printFigure(QStringLiteral("mqtt.qos1_acknowledged"), messages / ackedS,
                QStringLiteral("msg/s"), 0);
    printFigure(QStringLiteral("mqtt.qos1_to_subscriber"), messages / receivedS,
                QStringLiteral("msg/s"), 0);
}

// Returns -1 to go on, or the exit status to end with.
int parseOptions(const QStringList &args, Options *o) {
    QCommandLineParser p;
    p.addOptions(
        {{QStringLiteral("seconds"), QStringLiteral("Idle time measured (default 10)."),
          QStringLiteral("N")},
         {QStringLiteral("messages"), QStringLiteral("QoS 1 messages (default 20000)."),
          QStringLiteral("N")},
         {{QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Show this help.")}});
    if (!p.parse(QStringList{QStringLiteral("tipscope-bench mqtt")} + args)) {
        printError(p.errorText());
        return 2;
    }
    if (p.isSet(QStringLiteral("help"))) {
        QTextStream(stdout) << p.helpText();
        return 0;
    }
    if (p.isSet(QStringLiteral("seconds")))
        o->idleSeconds = p.value(QStringLiteral("seconds")).toInt();
    if (p.isSet(QStringLiteral("messages")))
        o->messages = p.value(QStringLiteral("messages")).toInt();
    if (o->idleSeconds < 1 || o->messages < 1) {
        printError(QStringLiteral("--seconds and --messages take whole numbers from 1"));
        return 2;
    }
    return -1;
}

} // namespace

int runMqttBench(const QStringList &args) {
    Options options;
    if (const int status = parseOptions(args, &options); status >= 0)
        return status;
    const QString whyNot = testing::MosquittoBroker::skipReason();
    if (!whyNot.isEmpty()) {
        printError(whyNot);
        return 1;
    }
    testing::MosquittoBroker broker;
    QString error;
    if (!broker.start(&error)) {
        printError(error);
        return 1;
    }
    MqttClient publisher;
    MqttClient subscriber;
    if (!subscriber.subscribe(QStringLiteral("tipscope/bench/#")).ok() ||
        !connectClient(subscriber, broker, QStringLiteral("bench-subscriber")) ||
        !connectClient(publisher, broker, QStringLiteral("bench-publisher"))) {
        printError(QStringLiteral("the clients did not connect: ") + publisher.problemText());
        return 1;
    }
    measureIdle(options.idleSeconds);
    measureQos1(publisher, subscriber, options.messages);
    return 0;
}

} // namespace tipscope::bench
