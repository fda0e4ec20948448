#include "plantpayloads.h"

#include "journal/jointexport.h"
#include "model/device/devicemodel.h"
#include "model/device/feedermodel.h"
#include "model/device/portmodel.h"
#include "model/device/stationmodel.h"

#include <cmath>

namespace tipscope::plant {

using journal::utcText;
using protocol::Role;
using protocol::Wording;

namespace {

// Rounded to the thousandth, so a tenth on the wire reads 57.9 and not 57.900000000000006.
QJsonValue optionalNumber(std::optional<qint64> value, double scale = 1) {
    return value ? QJsonValue(std::round(double(*value) * scale * 1000) / 1000) : QJsonValue();
}

QJsonValue addressValue(std::optional<int> address) {
    return address ? QJsonValue(QStringLiteral("%1").arg(*address, 2, 10, QLatin1Char('0')))
                   : QJsonValue();
}

// Stable English words for programs; PortStatus::text() is for people, in their language.
QString modeWord(model::PortStatus::Mode mode) {
    switch (mode) {
    case model::PortStatus::Mode::Working:
        return QStringLiteral("working");
    case model::PortStatus::Mode::Stand:
        return QStringLiteral("stand");
    case model::PortStatus::Mode::Sleep:
        return QStringLiteral("sleep");
    case model::PortStatus::Mode::Hibernation:
        return QStringLiteral("hibernation");
    }
    return {};
}

QString levelWord(model::Level level) {
    switch (level) {
    case model::Level::Unknown:
        return QStringLiteral("unknown");
    case model::Level::Ok:
        return QStringLiteral("ok");
    case model::Level::Info:
        return QStringLiteral("info");
    case model::Level::Warning:
        return QStringLiteral("warning");
    case model::Level::Error:
        return QStringLiteral("error");
    }
    return {};
}

// The field a counter's value goes under: its unit as people write it, made a JSON-friendly word.
QString unitField(const protocol::Unit *unit) {
    if (!unit || unit->display.isEmpty())
        return QStringLiteral("count");
    QString field = unit->display;
    field.replace(QLatin1Char('/'), QLatin1Char('_'));
    field.replace(QStringLiteral("%"), QStringLiteral("pct"));
    field.replace(QStringLiteral("°C"), QStringLiteral("c"));
    return field;
}

QString toolWord(const model::PortModel &port) {
    const auto tool = port.tool();
    return tool ? model::toolName(port.station().catalog(), port.station().family(), *tool,
                                  Wording::Catalog)
                : QString();
}

// An error code of 0 is "no error" in every table.
void addError(QJsonArray &alarms, std::optional<int> code, model::Level level, int port,
              const QString &text) {
    if (!code || *code == 0)
        return;
    QJsonObject alarm{{QStringLiteral("kind"), QStringLiteral("error")},
                      {QStringLiteral("code"), *code},
                      {QStringLiteral("level"), levelWord(qMax(model::Level::Warning, level))},
                      {QStringLiteral("text"), text}};
    if (port > 0)
        alarm.insert(QStringLiteral("port"), port);
    alarms.append(alarm);
}

} // namespace

QJsonObject statusPayload(bool online, const Publisher &publisher, qint64 nowMs, bool lineUp) {
    QJsonObject status{{QStringLiteral("ts"), utcText(nowMs)}, {QStringLiteral("online"), online}};
    if (online) {
        status.insert(QStringLiteral("agent"), publisher.agent);
        status.insert(QStringLiteral("version"), publisher.version);
        status.insert(QStringLiteral("line_up"), lineUp);
    }
    return status;
}

QJsonObject infoPayload(const model::DeviceModel &device, const QString &line,
                        const QString &deviceName, qint64 nowMs) {
    QJsonObject info{{QStringLiteral("ts"), utcText(nowMs)},
                     {QStringLiteral("model"), device.info().model},
                     {QStringLiteral("family"), device.family()},
                     {QStringLiteral("software"), device.info().softwareVersion},
                     {QStringLiteral("address"), addressValue(device.address())},
                     {QStringLiteral("line"), line},
                     {QStringLiteral("connection"), device.identity().line},
                     {QStringLiteral("name"), deviceName}};
    QJsonArray ports;
    if (const auto *station = qobject_cast<const model::StationModel *>(&device))
        for (const model::PortModel *port : station->ports()) {
            const QString tool = toolWord(*port);
            ports.append(QJsonObject{
                {QStringLiteral("port"), port->number()},
                {QStringLiteral("tool"), tool.isEmpty() ? QJsonValue() : QJsonValue(tool)}});
        }
    info.insert(QStringLiteral("ports"), ports);
    return info;
}

QJsonObject portLivePayload(const model::PortModel &port, qint64 readMs) {
    const auto status = port.status();
    const QString tool = toolWord(port);
    return {{QStringLiteral("ts"), utcText(readMs)},
            {QStringLiteral("tip_c"), optionalNumber(port.tipTemperature())},
            {QStringLiteral("set_c"), optionalNumber(port.selectedTemperature())},
            {QStringLiteral("power_pct"), optionalNumber(port.power(), 0.1)},
            {QStringLiteral("status"), status ? QJsonValue(modeWord(status->mode)) : QJsonValue()},
            {QStringLiteral("cooling"), status ? QJsonValue(status->cooling) : QJsonValue()},
            {QStringLiteral("tool"), tool.isEmpty() ? QJsonValue() : QJsonValue(tool)}};
}

QJsonObject feederLivePayload(const model::FeederModel &feeder, qint64 readMs) {
    const auto feeding = feeder.isFeeding();
    return {{QStringLiteral("ts"), utcText(readMs)},
            {QStringLiteral("fed_mm"), optionalNumber(feeder.fedLength(), 0.1)},
            {QStringLiteral("speed_mm_s"), optionalNumber(feeder.feedSpeed(), 0.1)},
            {QStringLiteral("status"),
             feeding ? QJsonValue(*feeding ? QStringLiteral("feeding") : QStringLiteral("idle"))
                     : QJsonValue()}};
}

QJsonObject countersPayload(const model::DeviceModel &device, qint64 nowMs) {
    QJsonArray counters;
    for (const model::Parameter *p : device.parameters(protocol::Group::Counter)) {
        const protocol::Unit *unit = device.catalog().unit(p->meta().unit);
        QJsonObject counter{{QStringLiteral("code"), QString::fromLatin1(p->code())},
                            {QStringLiteral("name"), p->meta().name},
                            {QStringLiteral("partial"), p->meta().partial},
                            {unitField(unit), optionalNumber(p->number(), unit ? unit->scale : 1)}};
        if (p->spec().port > 0)
            counter.insert(QStringLiteral("port"), p->spec().port);
        counters.append(counter);
    }
    return {{QStringLiteral("ts"), utcText(nowMs)}, {QStringLiteral("counters"), counters}};
}

QJsonArray activeAlarms(const model::DeviceModel &device) {
    QJsonArray alarms;
    const protocol::Catalog &catalog = device.catalog();
    if (const auto *station = qobject_cast<const model::StationModel *>(&device)) {
        const auto code = station->stationError();
        addError(alarms, code, station->stationErrorLevel(), 0,
                 code ? catalog.stationErrorText(device.family(), *code, Wording::Catalog) : "");
        for (const model::PortModel *port : station->ports()) {
            const auto portCode = port->error();
            addError(alarms, portCode, port->errorLevel(), port->number(),
                     portCode ? catalog.portErrorText(device.family(), *portCode, Wording::Catalog)
                              : QString());
            const auto alarm = port->alarm();
            if (alarm && alarm->high)
                alarms.append(QJsonObject{{QStringLiteral("kind"), QStringLiteral("alarm")},
                                          {QStringLiteral("port"), port->number()},
                                          {QStringLiteral("level"), QStringLiteral("warning")},
                                          {QStringLiteral("text"), "High temperature"}});
            if (alarm && alarm->low)
                alarms.append(QJsonObject{{QStringLiteral("kind"), QStringLiteral("alarm")},
                                          {QStringLiteral("port"), port->number()},
                                          {QStringLiteral("level"), QStringLiteral("warning")},
                                          {QStringLiteral("text"), "Low temperature"}});
        }
    } else if (const auto *feeder = qobject_cast<const model::FeederModel *>(&device)) {
        const auto code = feeder->errorCode();
        addError(alarms, code, feeder->errorLevel(), 0,
                 code ? catalog.feederErrorText(*code, Wording::Catalog) : QString());
    }
    return alarms;
}

QJsonObject alarmsPayload(const QJsonArray &alarms, qint64 nowMs) {
    return {{QStringLiteral("ts"), utcText(nowMs)}, {QStringLiteral("alarms"), alarms}};
}

QJsonObject eventPayload(const journal::StoredEvent &stored) {
    return journal::eventJson(stored);
}

} // namespace tipscope::plant
