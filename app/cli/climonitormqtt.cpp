// tipscope-cli monitor --mqtt HOST:PORT and/or --cfx amqp://HOST:PORT: a quick trial of the
// plant's MQTT and IPC-CFX without the service. The line the command line names (or every line of
// --workspace) runs in a PlantAgent, the same as tipscope-agent's, so the topics, messages and
// payloads are the agent's (docs/mqtt.md, docs/cfx.md). Every interval a line says where each
// stands: the broker, the devices, what was published and forwarded. The passwords come from the
// environment (TIPSCOPE_MQTT_PASSWORD, TIPSCOPE_CFX_PASSWORD), never from an argument.
#include "clicommands.h"

#include "link/tcptransport.h"
#include "mqtt/mqttclient.h"
#include "mqtt/mqttsecret.h"
#include "mqtt/mqtttopic.h"
#include "plant/plantagent.h"
#ifdef TIPSCOPE_WITH_CFX
#include "cfx/cfxpublisher.h"
#endif

#include <QDateTime>
#include <QEventLoop>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QSysInfo>
#include <QTimer>
#include <QUrl>
#include <cmath>

namespace tipscope::cli {

namespace {

struct CliMonitorMqttTr {
    Q_DECLARE_TR_FUNCTIONS(CliMonitorMqtt)
};

const char kPasswordVariable[] = "TIPSCOPE_MQTT_PASSWORD";
const char kCfxPasswordVariable[] = "TIPSCOPE_CFX_PASSWORD";

// --cfx amqp://HOST:PORT or amqps://HOST:PORT (TLS with the system's CAs), with its user and
// address; the agent configuration's "cfx" section has the rest (docs/cfx.md).
base::Outcome<cfx::CfxSettings> cfxOf(const CliOptions &o) {
    const QUrl url(o.values.value(QStringLiteral("cfx")), QUrl::StrictMode);
    const bool tls = url.scheme() == QLatin1String("amqps");
    if (!url.isValid() || (!tls && url.scheme() != QLatin1String("amqp")) || url.host().isEmpty() ||
        !url.userInfo().isEmpty() || (!url.path().isEmpty() && url.path() != QLatin1String("/")))
        return base::failure(
            CliMonitorMqttTr::tr("--cfx takes the AMQP broker as amqp://HOST:PORT or "
                                 "amqps://HOST:PORT (the user with --cfx-user, the password "
                                 "from %1)")
                .arg(QLatin1String(kCfxPasswordVariable)));
    cfx::CfxSettings s;
    s.host = url.host();
    s.tls = tls;
    s.port = url.port(tls ? 5671 : 5672);
    s.caFile = tls ? QStringLiteral("/etc/ssl/certs/ca-certificates.crt") : QString();
    s.username = o.values.value(QStringLiteral("cfx-user"));
    s.address = o.values.value(QStringLiteral("cfx-address"), s.address);
    if (!cfx::isBrokerAddress(s.address))
        return base::failure(CliMonitorMqttTr::tr(
            "--cfx-address takes RabbitMQ's form: /exchange/NAME, /exchange/NAME/KEY or "
            "/queue/NAME"));
    s.requestAddress = o.values.value(QStringLiteral("cfx-requests"));
    if (o.values.contains(QStringLiteral("cfx-requests")) && !cfx::isRequestQueue(s.requestAddress))
        return base::failure(
            CliMonitorMqttTr::tr("--cfx-requests takes a queue of the broker: /queue/NAME"));
    if (!s.username.isEmpty() && qEnvironmentVariableIsSet(kCfxPasswordVariable)) {
        auto password = mqtt::readSecretEnvironment(QLatin1String(kCfxPasswordVariable));
        if (!password)
            return base::failure(password.error());
        s.password = password.value();
    }
    return s;
}

base::Outcome<plant::AgentConfig> configOf(const CliOptions &o) {
    plant::AgentConfig c;
    QString host;
    quint16 port = 0;
    // --cfx alone publishes CFX only, as an agent configuration with "broker": false.
    c.mqtt = o.values.contains(QStringLiteral("mqtt"));
    if (c.mqtt &&
        !link::TcpTransport::parseHostPort(o.values.value(QStringLiteral("mqtt")), &host, &port))
        return base::failure(CliMonitorMqttTr::tr("--mqtt takes the broker as HOST:PORT"));
    c.broker.host = host;
    c.broker.port = port;
    c.broker.username = o.values.value(QStringLiteral("mqtt-user"));
    if (!c.broker.username.isEmpty() && qEnvironmentVariableIsSet(kPasswordVariable)) {
        auto password = mqtt::readSecretEnvironment(QLatin1String(kPasswordVariable));
        if (!password)
            return base::failure(password.error());
        c.broker.password = password.value();
    }
    c.site = o.values.value(QStringLiteral("site"), QStringLiteral("site"));
    if (c.site.trimmed().isEmpty())
        return base::failure(CliMonitorMqttTr::tr("--site takes the site's name"));
    bool ok = true;
    c.live.intervalMs =
        o.values.value(QStringLiteral("interval"), QStringLiteral("1000")).toInt(&ok);
    if (!ok || c.live.intervalMs < 100 || c.live.intervalMs > 3600000)
        return base::failure(
            CliMonitorMqttTr::tr("--interval takes milliseconds from 100 to 3600000"));
    c.journalPath = o.values.value(QStringLiteral("journal"));
    if (o.values.contains(QStringLiteral("cfx"))) {
        auto cfx = cfxOf(o);
        if (!cfx)
            return base::failure(cfx.error());
        c.cfx = cfx.value();
    }
    // Not the agent's own id, so a trial beside a running agent does not take its session over.
    c.broker.clientId = QStringLiteral("tipscope-cli-%1-%2")
                            .arg(QSysInfo::machineHostName(), mqtt::sanitizeTopicLevel(c.site));
    if (o.workspace.isEmpty()) {
        c.workspace.lines = {workspaceLineOf(o)};
    } else {
        auto file = model::WorkspaceFile::load(o.workspace);
        if (!file)
            return base::failure(file.error());
        c.workspace = file.value();
        c.workspacePath = o.workspace;
    }
    return c;
}

QString mqttStanding(const plant::PlantPublisher &p) {
    qint64 live = 0;
    for (const auto &device : p.devices())
        live += device->liveCount();
    const mqtt::MqttClient *client = p.client();
    using State = mqtt::MqttClient::State;
    const State state = client->state();
    const QString broker = state == State::Connected ? CliMonitorMqttTr::tr("Broker connected.")
                           : state == State::Stopped || state == State::Stopping
                               ? CliMonitorMqttTr::tr("Broker disconnected.")
                           : client->problemText().isEmpty()
                               ? CliMonitorMqttTr::tr("Connecting to the broker.")
                               : client->problemText();
    return CliMonitorMqttTr::tr(
               "%n device(s), %1 live messages, %2 joints and events forwarded, %3 waiting. %4",
               nullptr, int(p.devices().size()))
        .arg(live)
        .arg(p.forwarder()->acknowledgedCount())
        .arg(p.forwarder()->waitingCount())
        .arg(broker);
}

QString standing(const plant::PlantAgent &agent) {
    QStringList parts;
    if (const plant::PlantPublisher *p = agent.publisher())
        parts.append(mqttStanding(*p));
#ifdef TIPSCOPE_WITH_CFX
    if (cfx::CfxPublisher *c = agent.cfxPublisher()) {
        const bool up = c->sender().state() == cfx::AmqpSender::State::Connected;
        parts.append(
            CliMonitorMqttTr::tr("CFX: %1 messages from the journal accepted, %2 waiting. %3")
                .arg(c->forwarder().acceptedCount())
                .arg(c->forwarder().waitingCount())
                .arg(up ? CliMonitorMqttTr::tr("Broker connected.")
                        : CliMonitorMqttTr::tr("Connecting to the broker.")));
    }
#endif
    return parts.join(QStringLiteral("  "));
}

// Whether a broker was ever reached, MQTT's or CFX's: never reached is a transport error.
void watchConnected(plant::PlantAgent &agent, QObject *context, bool &connected) {
    if (const plant::PlantPublisher *p = agent.publisher())
        QObject::connect(p->client(), &mqtt::MqttClient::connected, context,
                         [&connected] { connected = true; });
#ifdef TIPSCOPE_WITH_CFX
    if (cfx::CfxPublisher *c = agent.cfxPublisher())
        QObject::connect(&c->sender(), &cfx::AmqpSender::connected, context,
                         [&connected] { connected = true; });
#endif
}

} // namespace

int runMonitorPlant(const CliOptions &o, QTextStream &out, QTextStream &err) {
    const auto config = configOf(o);
    if (!config) {
        err << "tipscope-cli: " << config.error() << Qt::endl;
        return kUsage;
    }
    if (!config->broker.username.isEmpty() && config->broker.password.isEmpty())
        err << CliMonitorMqttTr::tr(
                   "tipscope-cli: %1 is not set: connecting as %2 without a password")
                   .arg(QLatin1String(kPasswordVariable), config->broker.username)
            << Qt::endl;
    bool ok = true;
    const double durationS =
        o.values.value(QStringLiteral("duration"), QStringLiteral("0")).toDouble(&ok);
    if (!ok || !std::isfinite(durationS) || durationS < 0 || durationS > 1e9) {
        err << CliMonitorMqttTr::tr("tipscope-cli: --duration takes seconds") << Qt::endl;
        return kUsage;
    }
    if (!o.verbose) // every MQTT state change and request is for --verbose
        QLoggingCategory::setFilterRules(QStringLiteral("*.debug=false"));
    plant::PlantAgent agent(
        {QStringLiteral("tipscope-cli"), QCoreApplication::applicationVersion()});
    QEventLoop loop;
    QObject::connect(&agent, &plant::PlantAgent::finished, &loop, &QEventLoop::quit);
    agent.start(config.value());
    bool connected = false;
    watchConnected(agent, &loop, connected);
    QTimer report;
    QObject::connect(&report, &QTimer::timeout, &loop, [&] {
        out << QDateTime::currentDateTime().toString(Qt::ISODateWithMs) << "  " << standing(agent)
            << Qt::endl;
    });
    report.start(config->live.intervalMs);
    if (durationS > 0)
        QTimer::singleShot(qint64(durationS * 1000), &agent, &plant::PlantAgent::stop);
    loop.exec();
    out << standing(agent) << Qt::endl;
    if (!agent.failure().isEmpty()) {
        err << "tipscope-cli: " << agent.failure() << Qt::endl;
        return kTransport;
    }
    return connected ? kOk : kTransport; // never reached the broker: a transport error
}

} // namespace tipscope::cli
