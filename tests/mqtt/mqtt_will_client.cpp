// A client for tst_mqttwill to kill: connects to the broker on 127.0.0.1 at the port given,
// with the keep-alive given and a retained last will {"online": false} on the topic given,
// publishes a retained {"online": true} there, prints "ready" once the broker acknowledged it,
// and waits for ever.
#include "mqtt/mqttclient.h"

#include <QCoreApplication>
#include <cstdio>

using namespace tipscope::mqtt;

int main(int argc, char *argv[]) {
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 4) {
        std::fprintf(stderr, "usage: mqtt_will_client PORT TOPIC KEEPALIVE\n");
        return 2;
    }
    MqttSettings settings;
    settings.host = QStringLiteral("127.0.0.1");
    settings.port = args.at(1).toInt();
    settings.clientId = QStringLiteral("will-client");
    settings.keepAliveSeconds = args.at(3).toInt();
    settings.will = {args.at(2), R"({"online": false})", 1, true};
    MqttClient client;
    client.setSettings(settings);
    int statusId = -1;
    QObject::connect(&client, &MqttClient::connected, &client, [&] {
        statusId = client.publish(args.at(2), R"({"online": true})", 1, true).messageId;
    });
    QObject::connect(&client, &MqttClient::published, &client, [&](int messageId) {
        if (messageId == statusId) {
            std::printf("ready\n");
            std::fflush(stdout);
        }
    });
    QObject::connect(
        &client, &MqttClient::problemOccurred, &client,
        [](MqttProblem, const QString &text) { std::fprintf(stderr, "%s\n", qPrintable(text)); });
    client.start();
    return app.exec();
}
