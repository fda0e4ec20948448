#include "appsettings.h"

#include "link/tcptransport.h"

#include <QCoreApplication>
#include <QSettings>

namespace tipscope::model {

namespace {
struct AppSettingsTr {
    Q_DECLARE_TR_FUNCTIONS(AppSettings)
};

int intIn(QSettings &s, const char *key, int fallback, int lo, int hi) {
    bool ok = false;
    const int v = s.value(QLatin1String(key)).toInt(&ok);
    return ok && v >= lo && v <= hi ? v : fallback;
}

QString oneOf(QSettings &s, const char *key, const QStringList &allowed, const QString &fallback) {
    const QString v = s.value(QLatin1String(key)).toString();
    return allowed.contains(v) ? v : fallback;
}

const QStringList kKinds = {QStringLiteral("serial"), QStringLiteral("tcp"),
                            QStringLiteral("demo")};
const QStringList kAddressing = {QStringLiteral("auto"), QStringLiteral("with"),
                                 QStringLiteral("without")};
} // namespace

AppSettings AppSettings::load(QSettings &s) {
    AppSettings a;
    a.kind = Kind(kKinds.indexOf(oneOf(s, "connection/kind", kKinds, QStringLiteral("demo"))));
    a.serialPort = s.value(QStringLiteral("connection/port")).toString().left(256);
    QString host;
    quint16 port = 0;
    const QString tcp = s.value(QStringLiteral("connection/tcp")).toString();
    if (link::TcpTransport::parseHostPort(tcp, &host, &port))
        a.tcpAddress = tcp;
    a.baud = intIn(s, "line/baud", 19200, 50, 4'000'000);
    a.parity = oneOf(s, "line/parity",
                     {QStringLiteral("none"), QStringLiteral("even"), QStringLiteral("odd")},
                     QStringLiteral("none"));
    a.stopBits = intIn(s, "line/stopBits", 1, 1, 2);
    a.addressing = Session::Addressing(
        kAddressing.indexOf(oneOf(s, "line/addressing", kAddressing, QStringLiteral("auto"))));
    a.robotAddress = intIn(s, "line/robotAddress", 0, 0, 99);
    a.targetAddress = intIn(s, "line/targetAddress", 1, 0, 99);
    a.unit = oneOf(s, "prefs/temperatureUnit", {QStringLiteral("C"), QStringLiteral("F")},
                   QStringLiteral("C")) == QLatin1String("F")
                 ? TemperatureUnit::Fahrenheit
                 : TemperatureUnit::Celsius;
    a.liveMs = intIn(s, "poll/liveMs", 250, 50, 60'000);
    a.statusMs = intIn(s, "poll/statusMs", 2000, 100, 600'000);
    a.counterMs = intIn(s, "poll/counterMs", 60000, 1000, 3'600'000);
    a.turnaroundMs = intIn(s, "link/turnaroundMs", 100, 5, 10'000);
    a.retries = intIn(s, "link/retries", 2, 0, 10);
    a.language = oneOf(s, "ui/language",
                       {QStringLiteral("system"), QStringLiteral("en"), QStringLiteral("es"),
                        QStringLiteral("de")},
                       QStringLiteral("system"));
    a.fullRateMinutes = intIn(s, "telemetry/fullRateMinutes", a.fullRateMinutes, 10, 24 * 60);
    a.historyHours = intIn(s, "telemetry/historyHours", a.historyHours, 1, 7 * 24);
    return a;
}

void AppSettings::save(QSettings &s) const {
    s.setValue(QStringLiteral("connection/kind"), kKinds.value(int(kind)));
    s.setValue(QStringLiteral("connection/port"), serialPort);
    s.setValue(QStringLiteral("connection/tcp"), tcpAddress);
    s.setValue(QStringLiteral("line/baud"), baud);
    s.setValue(QStringLiteral("line/parity"), parity);
    s.setValue(QStringLiteral("line/stopBits"), stopBits);
    s.setValue(QStringLiteral("line/addressing"), kAddressing.value(int(addressing)));
    s.setValue(QStringLiteral("line/robotAddress"), robotAddress);
    s.setValue(QStringLiteral("line/targetAddress"), targetAddress);
    s.setValue(QStringLiteral("prefs/temperatureUnit"),
               unit == TemperatureUnit::Fahrenheit ? QStringLiteral("F") : QStringLiteral("C"));
    s.setValue(QStringLiteral("poll/liveMs"), liveMs);
    s.setValue(QStringLiteral("poll/statusMs"), statusMs);
    s.setValue(QStringLiteral("poll/counterMs"), counterMs);
    s.setValue(QStringLiteral("link/turnaroundMs"), turnaroundMs);
    s.setValue(QStringLiteral("link/retries"), retries);
    s.setValue(QStringLiteral("ui/language"), language);
    s.setValue(QStringLiteral("telemetry/fullRateMinutes"), fullRateMinutes);
    s.setValue(QStringLiteral("telemetry/historyHours"), historyHours);
}

TelemetryTiers AppSettings::telemetryTiers() const {
    TelemetryTiers t;
    t.fullRateMs = qint64(fullRateMinutes) * TelemetryTiers::kMinuteMs;
    t.historyMs = qMax(t.fullRateMs, qint64(historyHours) * TelemetryTiers::kHourMs);
    return t;
}

base::Outcome<Session::Settings> AppSettings::sessionSettings() const {
    Session::Settings s;
    s.addressing = addressing;
    s.targetAddress = targetAddress;
    s.line.queue.robotAddress = robotAddress;
    s.line.queue.turnaroundMs = turnaroundMs;
    s.line.queue.retries = retries;
    s.line.serial.baudRate = baud;
    s.line.serial.parity = parity == QLatin1String("even")  ? QSerialPort::EvenParity
                           : parity == QLatin1String("odd") ? QSerialPort::OddParity
                                                            : QSerialPort::NoParity;
    s.line.serial.stopBits = stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop;
    switch (kind) {
    case Kind::Demo:
        s.line.kind = link::LineSettings::Kind::Demo;
        s.demoActivity = true; // people try the demo to see what the charts show
        break;
    case Kind::Serial:
        if (serialPort.trimmed().isEmpty())
            return base::failure(AppSettingsTr::tr("choose a serial port"));
        s.line.kind = link::LineSettings::Kind::Serial;
        s.line.serial.portName = serialPort.trimmed();
        break;
    case Kind::Tcp:
        if (!link::TcpTransport::parseHostPort(tcpAddress.trimmed(), &s.line.tcpHost,
                                               &s.line.tcpPort))
            return base::failure(
                AppSettingsTr::tr("'%1' is not HOST:PORT (for example 192.168.1.20:4001)")
                    .arg(tcpAddress));
        s.line.kind = link::LineSettings::Kind::Tcp;
        break;
    }
    return s;
}

} // namespace tipscope::model
