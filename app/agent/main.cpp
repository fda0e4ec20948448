// tipscope-agent: the line service. Runs a workspace's lines without a screen, keeps every joint
// and event in the journal and publishes the lines to the plant's MQTT broker (docs/mqtt.md).
// Meant to run under systemd (packaging/systemd/tipscope-agent.service): it logs to standard
// error with journald's priority prefixes, reloads its configuration on SIGHUP and stops cleanly
// on SIGTERM, publishing every device offline first.
#include "journaldlog.h"
#include "unixsignals.h"

#include "i18n/translations.h"
#include "link/epolldispatcher.h"
#include "mqtt/mqttsetup.h"
#include "plant/plantagent.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QTextStream>

using namespace tipscope;

namespace {

struct AgentMainTr {
    Q_DECLARE_TR_FUNCTIONS(AgentMain)
};

constexpr int kExitUsage = 2;
// The journal cannot be used (PlantAgent::failure()): systemd shows the service failed.
constexpr int kExitJournal = 3;
const QString kDefaultConfig = QStringLiteral("/etc/tipscope/agent.json");

QString summary(const plant::AgentConfig &c) {
    const QString who = c.broker.username.isEmpty() ? AgentMainTr::tr("without a user name")
                        : c.passwordSource.isEmpty()
                            ? AgentMainTr::tr("as %1, without a password").arg(c.broker.username)
                            : AgentMainTr::tr("as %1, password from the %2")
                                  .arg(c.broker.username, c.passwordSource);
    QStringList lines;
    for (const model::WorkspaceLine &line : c.workspace.lines)
        lines << line.name;
    if (!c.mqtt)
        return AgentMainTr::tr("site %1, %n line(s) (%2), no MQTT broker: CFX only", nullptr,
                               int(lines.size()))
            .arg(c.site, lines.join(QStringLiteral(", ")));
    return AgentMainTr::tr("site %1, %n line(s) (%2), broker %3:%4%5 %6", nullptr,
                           int(lines.size()))
        .arg(c.site, lines.join(QStringLiteral(", ")), c.broker.host)
        .arg(c.broker.port)
        .arg(c.broker.tls.caFile.isEmpty() ? QString() : AgentMainTr::tr(" with TLS"), who);
}

} // namespace

int main(int argc, char *argv[]) {
    // Dozens of lines whose answers come a byte or two at a time: each turn of the loop costs
    // what is ready, not what is watched (docs/performance.md). TIPSCOPE_EVENT_LOOP=qt keeps Qt's.
    (void)link::useEpollUnlessTold();
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("tipscope-agent"));
    QCoreApplication::setApplicationVersion(QStringLiteral(TIPSCOPE_VERSION));
    i18n::installTranslators(app, QStringLiteral("system"));

    QCommandLineParser parser;
    parser.setApplicationDescription(AgentMainTr::tr(
        "Runs the lines of a workspace without a screen, keeps their joints and events in "
        "the journal and publishes them to an MQTT broker."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption configOption(
        QStringLiteral("config"),
        AgentMainTr::tr("The agent's configuration (default %1).").arg(kDefaultConfig),
        AgentMainTr::tr("file"), kDefaultConfig);
    const QCommandLineOption checkOption(
        QStringLiteral("check"),
        AgentMainTr::tr(
            "Reads the configuration and its workspace, says what is wrong, and exits."));
    parser.addOptions({configOption, checkOption});
    parser.process(app);
    if (!parser.positionalArguments().isEmpty()) {
        QTextStream(stderr)
            << "tipscope-agent: "
            << AgentMainTr::tr("unexpected argument %1").arg(parser.positionalArguments()[0])
            << Qt::endl;
        return kExitUsage;
    }

    agent::installJournaldLog();
    // Debug lines (every MQTT state, every request) only when asked: QT_LOGGING_RULES overrides.
    QLoggingCategory::setFilterRules(QStringLiteral("*.debug=false"));
    const QString path = parser.value(configOption);
    auto config = plant::AgentConfig::load(path);
    if (!config) {
        qCritical("%s", qPrintable(config.error()));
        return kExitUsage;
    }
    if (parser.isSet(checkOption)) {
        if (const auto tls = mqtt::checkTlsFiles(config->broker.tls); !tls) {
            qCritical("%s", qPrintable(AgentMainTr::tr("%1: %2").arg(path, tls.error())));
            return kExitUsage;
        }
        qInfo("%s",
              qPrintable(AgentMainTr::tr("%1 is good: %2").arg(path, summary(config.value()))));
        return 0;
    }

    plant::PlantAgent agent({QStringLiteral("tipscope-agent"), app.applicationVersion()});
    agent::UnixSignals signals;
    QObject::connect(&signals, &agent::UnixSignals::stopRequested, &agent,
                     &plant::PlantAgent::stop);
    QObject::connect(&signals, &agent::UnixSignals::reloadRequested, &agent, [&agent, path] {
        const auto reloaded = plant::AgentConfig::load(path);
        if (!reloaded) {
            qCritical("%s",
                      qPrintable(AgentMainTr::tr("configuration refused, the running one stays: %1")
                                     .arg(reloaded.error())));
            return;
        }
        qInfo("%s", qPrintable(AgentMainTr::tr("reloading: %1").arg(summary(reloaded.value()))));
        agent.reload(reloaded.value());
    });
    QObject::connect(&agent, &plant::PlantAgent::finished, &app, &QCoreApplication::quit);
    qInfo("%s", qPrintable(AgentMainTr::tr("tipscope-agent %1 starting: %2")
                               .arg(app.applicationVersion(), summary(config.value()))));
    agent.start(config.value());
    const int rc = app.exec();
    if (!agent.failure().isEmpty()) {
        qCritical("%s", qPrintable(AgentMainTr::tr("stopped: %1").arg(agent.failure())));
        return kExitJournal;
    }
    qInfo("%s", qPrintable(AgentMainTr::tr("stopped")));
    return rc;
}
