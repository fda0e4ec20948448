// tipscope: the desktop application.
#include "i18n/translations.h"
#include "link/tcptransport.h"
#include "mainwindow.h"
#include "model/appsettings.h"
#include "screenshots.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QSettings>
#include <QTextStream>
#include <QTimer>
#include <memory>

using namespace tipscope::gui;
using tipscope::model::AppSettings;

namespace {
// Over SSH there is no display, and Qt aborts without one before the command line is read. There
// the offscreen platform stands in, so that what only prints (--help, --version, an option's
// error) and --screenshots work; opening the window is refused with the reason.
bool withoutDisplay() {
    return qEnvironmentVariableIsEmpty("DISPLAY") &&
           qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
           qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
}
} // namespace

int main(int argc, char *argv[]) {
    const bool headless = withoutDisplay();
    if (headless)
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("TipScope"));
    QApplication::setOrganizationName(QStringLiteral("TipScope"));
    QApplication::setApplicationVersion(QStringLiteral(TIPSCOPE_VERSION));
    QApplication::setDesktopFileName(QStringLiteral("tipscope"));
    // The language is chosen in Preferences (ui/language) and takes effect here, before the first
    // translated string, the command-line help included.
    AppSettings start = AppSettings::load(*std::make_unique<QSettings>());
    tipscope::i18n::installTranslators(app, start.language);
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/tipscope/icons/tipscope-256.png")));

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate(
        "main", "Configure and monitor JBC soldering stations and the SFR feeder."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption demo(
        QStringLiteral("demo"),
        QApplication::translate("main",
                                "Start on the built-in simulated DME station and SFR feeder."));
    const QCommandLineOption port(QStringLiteral("port"),
                                  QApplication::translate("main", "Connect to this serial port."),
                                  QStringLiteral("DEVICE"));
    const QCommandLineOption tcp(QStringLiteral("tcp"),
                                 QApplication::translate("main", "Connect to a TCP serial server."),
                                 QStringLiteral("HOST:PORT"));
    const QCommandLineOption workspace(
        QStringLiteral("workspace"),
        QApplication::translate("main", "Open the lines of this workspace file."),
        QStringLiteral("FILE"));
    const QCommandLineOption shots(
        QStringLiteral("screenshots"),
        QApplication::translate("main", "Save a PNG of every page into DIR, then quit."),
        QStringLiteral("DIR"));
    const QCommandLineOption plant(
        QStringLiteral("plant"),
        QApplication::translate("main", "Watch the devices published to this MQTT broker on the "
                                        "fleet overview."),
        QStringLiteral("HOST:PORT"));
    const QCommandLineOption plantSite(
        QStringLiteral("plant-site"),
        QApplication::translate("main", "With --plant: only this site's devices."),
        QStringLiteral("SITE"));
    parser.addOptions({demo, port, tcp, workspace, shots, plant, plantSite});
    parser.process(app);
    if (headless && !parser.isSet(shots)) {
        QTextStream(stderr) << QApplication::translate(
                                   "main", "tipscope: there is no display (neither DISPLAY nor "
                                           "WAYLAND_DISPLAY is set); start it on a desktop, or "
                                           "use tipscope-cli")
                            << Qt::endl;
        return 1;
    }

    MainWindow window;
    window.show();
    bool connectNow = false;
    // Screenshots are of the demo line, or of the workspace when one is given.
    if (parser.isSet(demo) || (parser.isSet(shots) && !parser.isSet(workspace))) {
        start.kind = AppSettings::Kind::Demo;
        connectNow = true;
    } else if (parser.isSet(port)) {
        start.kind = AppSettings::Kind::Serial;
        start.serialPort = parser.value(port);
        connectNow = true;
    } else if (parser.isSet(tcp)) {
        start.kind = AppSettings::Kind::Tcp;
        start.tcpAddress = parser.value(tcp);
        connectNow = true;
    }
    if (connectNow)
        window.connectWith(start);
    if (parser.isSet(workspace)) {
        if (const QString refused = window.openWorkspace(parser.value(workspace));
            !refused.isEmpty()) {
            QTextStream(stderr) << QApplication::translate("main", "tipscope: %1").arg(refused)
                                << Qt::endl;
            return 2;
        }
    } else if (!connectNow) {
        window.reopenLastWorkspace();
    }
    if (parser.isSet(plant)) {
        tipscope::mqtt::MqttSettings broker;
        quint16 brokerPort = 0;
        if (!tipscope::link::TcpTransport::parseHostPort(parser.value(plant), &broker.host,
                                                         &brokerPort)) {
            QTextStream(stderr) << QApplication::translate(
                                       "main", "tipscope: --plant takes the broker as HOST:PORT")
                                << Qt::endl;
            return 2;
        }
        broker.port = brokerPort;
        window.watchPlant(broker, parser.value(plantSite));
    }
    if (parser.isSet(shots))
        takeScreenshots(window, parser.value(shots));
    return QApplication::exec();
}
