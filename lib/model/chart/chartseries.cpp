#include "model/chart/chartseries.h"

#include "model/live/telemetryrecorder.h"
#include "model/session.h"
#include "protocol/catalog.h"

#include <QCoreApplication>
#include <QLocale>
#include <QSet>
#include <cmath>
#include <limits>

namespace tipscope::model {

namespace {
struct ChartSeriesTr {
    Q_DECLARE_TR_FUNCTIONS(ChartSeries)
};

// The wire unit of each telemetry series, as the catalog names it (TTx, STx: degC; PPx: permille;
// FDL: dmm; SPD: dmmPerSecond), so the chart scales exactly as the settings pages do.
QString wireUnit(const QString &series) {
    if (series == QLatin1String("tip") || series == QLatin1String("setpoint") ||
        isHardwareSeries(series))
        return QStringLiteral("degC");
    if (series == QLatin1String("power"))
        return QStringLiteral("permille");
    if (series == QLatin1String("fed"))
        return QStringLiteral("dmm");
    if (series == QLatin1String("speed"))
        return QStringLiteral("dmmPerSecond");
    return {};
}

// A curve's name in a legend, whole per language: German writes its nouns capitalised
// ("P1 Lötspitze") where English writes "P1 tip", so neither is made from the title by
// lower-casing it and putting "P1" before it.
struct TraceNames {
    const char *series;
    const char *alone;  // a feeder's curve, the station's transformer, a kind of curve
    const char *onPort; // nullptr: the curve is never a port's
};
constexpr TraceNames kTraceNames[] = {
    {"tip", QT_TRANSLATE_NOOP("ChartSeries", "tip"), QT_TRANSLATE_NOOP("ChartSeries", "P%1 tip")},
    {"setpoint", QT_TRANSLATE_NOOP("ChartSeries", "setpoint"),
     QT_TRANSLATE_NOOP("ChartSeries", "P%1 setpoint")},
    {"power", QT_TRANSLATE_NOOP("ChartSeries", "power"),
     QT_TRANSLATE_NOOP("ChartSeries", "P%1 power")},
    {"status", QT_TRANSLATE_NOOP("ChartSeries", "status"),
     QT_TRANSLATE_NOOP("ChartSeries", "P%1 status")},
    {"fed", QT_TRANSLATE_NOOP("ChartSeries", "fed length"), nullptr},
    {"speed", QT_TRANSLATE_NOOP("ChartSeries", "speed"), nullptr},
    {"feeding", QT_TRANSLATE_NOOP("ChartSeries", "feeding"), nullptr},
    {"transistor", QT_TRANSLATE_NOOP("ChartSeries", "transistor"),
     QT_TRANSLATE_NOOP("ChartSeries", "P%1 transistor")},
    {"transformer", QT_TRANSLATE_NOOP("ChartSeries", "transformer"), nullptr},
};

std::optional<qint64> numberOf(const Parameter *p) {
    return p ? p->number() : std::nullopt;
}
} // namespace

std::optional<qint32> SeriesFormat::toWire(double display) const {
    if (!std::isfinite(display) || scale == 0)
        return std::nullopt;
    const double wire = std::round((display - offset) / scale);
    if (wire < double(std::numeric_limits<qint32>::min()) ||
        wire > double(std::numeric_limits<qint32>::max()))
        return std::nullopt;
    return qint32(wire);
}

QString SeriesFormat::format(double display) const {
    const QString number = QLocale().toString(display, 'f', decimals);
    return unit.isEmpty() ? number : number + QLatin1Char(' ') + unit;
}

SeriesFormat seriesFormat(const QString &series, TemperatureUnit unit) {
    SeriesFormat f;
    const QString key = wireUnit(series);
    if (key == QLatin1String("degC")) {
        const bool fahrenheit = unit == TemperatureUnit::Fahrenheit;
        f.scale = fahrenheit ? 1.8 : 1;
        f.offset = fahrenheit ? 32 : 0;
        // °F of a whole °C has a fraction; one decimal keeps the CSV exact.
        f.decimals = fahrenheit ? 1 : 0;
        f.unit = fahrenheit ? QStringLiteral("°F") : QStringLiteral("°C");
    } else if (const protocol::Unit *u = protocol::Catalog::builtin().unit(key)) {
        f.scale = u->scale;
        f.decimals = u->decimals;
        f.unit = u->display;
    } else {
        f.plotted = false;
    }
    f.axis = series == QLatin1String("power") || series == QLatin1String("speed") ? ChartAxis::Right
                                                                                  : ChartAxis::Left;
    return f;
}

QString seriesTitle(const QString &series) {
    if (series == QLatin1String("tip"))
        return ChartSeriesTr::tr("Tip");
    if (series == QLatin1String("setpoint"))
        return ChartSeriesTr::tr("Setpoint");
    if (series == QLatin1String("power"))
        return ChartSeriesTr::tr("Power");
    if (series == QLatin1String("status"))
        return ChartSeriesTr::tr("Status");
    if (series == QLatin1String("fed"))
        return ChartSeriesTr::tr("Fed length");
    if (series == QLatin1String("speed"))
        return ChartSeriesTr::tr("Speed");
    if (series == QLatin1String("feeding"))
        return ChartSeriesTr::tr("Feeding");
    if (series == QLatin1String("transistor"))
        return ChartSeriesTr::tr("Transistor");
    if (series == QLatin1String("transformer"))
        return ChartSeriesTr::tr("Transformer");
    return series;
}

QString traceName(const QString &series, int port) {
    for (const TraceNames &n : kTraceNames) {
        if (series != QLatin1String(n.series))
            continue;
        if (port == 0 || !n.onPort)
            return QCoreApplication::translate("ChartSeries", n.alone);
        return QCoreApplication::translate("ChartSeries", n.onPort).arg(port);
    }
    return port == 0 ? series : ChartSeriesTr::tr("P%1 %2").arg(port).arg(series);
}

QList<ChartChannel> sessionChannels(Session &session) {
    QList<ChartChannel> out;
    const auto describe = [](const DeviceModel &d, ChartChannel &c) {
        c.deviceModel = d.info().model;
        c.deviceName = d.displayName();
        c.address = d.info().addressText();
        c.softwareVersion = d.info().softwareVersion;
        c.device = d.identity();
    };
    for (DeviceModel *d : session.devices()) {
        if (auto *station = qobject_cast<StationModel *>(d)) {
            for (PortModel *port : station->ports()) {
                ChartChannel c;
                c.key = TelemetryRecorder::keyOf(*station, port->number());
                c.port = port->number();
                c.id = QStringLiteral("port%1").arg(c.port);
                c.title = ChartSeriesTr::tr("Port %1").arg(c.port);
                describe(*station, c);
                c.tool = port->tool() ? port->toolName() : QString();
                if (const auto high = numberOf(port->parameter(protocol::Role::HighAlarm)))
                    c.highAlarm = qint32(*high);
                if (const auto low = numberOf(port->parameter(protocol::Role::LowAlarm)))
                    c.lowAlarm = qint32(*low);
                if (const auto *buffer = session.telemetry().buffer(c.key))
                    c.series = buffer->seriesNames();
                out.append(c);
            }
        } else if (auto *feeder = qobject_cast<FeederModel *>(d)) {
            ChartChannel c;
            c.key = TelemetryRecorder::keyOf(*feeder, 0);
            c.id = QStringLiteral("feeder");
            c.title = ChartSeriesTr::tr("Feeder");
            describe(*feeder, c);
            if (const auto *buffer = session.telemetry().buffer(c.key))
                c.series = buffer->seriesNames();
            out.append(c);
        }
    }
    return out;
}

QColor portColor(int port) {
    // Distinguishable for the common colour-vision deficiencies (Okabe-Ito).
    static const QColor kColors[] = {QColor(0x00, 0x72, 0xB2), QColor(0xD5, 0x5E, 0x00),
                                     QColor(0x00, 0x9E, 0x73), QColor(0xCC, 0x79, 0xA7),
                                     QColor(0x56, 0xB4, 0xE9), QColor(0xE6, 0x9F, 0x00)};
    return kColors[qMax(0, port - 1) % int(std::size(kColors))];
}

bool isHardwareSeries(const QString &series) {
    return series == QLatin1String("transistor") || series == QLatin1String("transformer");
}

QList<ChartTrace> tracesFor(const QList<ChartChannel> &channels, const QList<int> &which,
                            TemperatureUnit unit, bool hardware) {
    QList<ChartTrace> out;
    QSet<QString> transformers; // one curve per station, however many of its ports are shown
    for (int index : which) {
        const ChartChannel &c = channels.at(index);
        const QColor base = c.isFeeder() ? portColor(1) : portColor(c.port);
        for (const QString &series : c.series) {
            ChartTrace t{index, series,        traceName(series, c.port),
                         base,  Qt::SolidLine, seriesFormat(series, unit)};
            if (!t.format.plotted || (isHardwareSeries(series) && !hardware))
                continue;
            if (series == QLatin1String("transformer")) {
                if (transformers.contains(c.address))
                    continue;
                transformers.insert(c.address);
                t.name = traceName(series, 0);
                t.color = QColor(0x55, 0x55, 0x55);
                t.style = Qt::DashDotDotLine;
            } else if (series == QLatin1String("transistor")) {
                t.color = base.darker(150);
                t.style = Qt::DashDotLine;
            } else if (series == QLatin1String("setpoint")) {
                t.style = Qt::DashLine;
            } else if (series == QLatin1String("power") || series == QLatin1String("speed")) {
                t.style = Qt::DotLine;
                t.color = c.isFeeder() ? portColor(2) : base.lighter(130);
            }
            out.append(t);
        }
    }
    return out;
}

} // namespace tipscope::model
