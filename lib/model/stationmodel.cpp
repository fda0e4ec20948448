#include "stationmodel.h"

#include "eventlog.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(StationModel)
};

Event::Severity severityOf(const QString &tableName, int code) {
    const QString s = Catalog::builtin().severity(tableName, code);
    if (s == QLatin1String("error"))
        return Event::Severity::Error;
    if (s == QLatin1String("warning"))
        return Event::Severity::Warning;
    return Event::Severity::Info;
}
} // namespace

StationModel::StationModel(link::RequestQueue &queue, const link::DeviceInfo &info, QObject *parent)
    : DeviceModel(queue, info, parent) {
    for (int p = 1; p <= familyInfo().ports; ++p)
        m_ports.append(new PortModel(*this, p, this));
}

QList<Parameter *> StationModel::stationSettings() const {
    QList<Parameter *> out;
    for (const char *code : {"MAT", "MIT", "PLM"})
        if (Parameter *p = parameter(code))
            out.append(p);
    return out;
}

QList<Parameter *> StationModel::dispensingSettings() const {
    QList<Parameter *> out;
    for (Parameter *p : parameters())
        if (p->meta().group == Group::Dispensing)
            out.append(p);
    return out;
}

std::optional<int> StationModel::stationError() const {
    const Parameter *p = parameter("SER");
    return p && p->number() ? std::optional<int>(int(*p->number())) : std::nullopt;
}

QString StationModel::stationErrorText() const {
    const auto e = stationError();
    return e ? Catalog::builtin().stationErrorText(family(), *e, Wording::Translated) : Tr::tr("—");
}

std::optional<qint64> StationModel::transformerTemperature() const {
    const Parameter *p = parameter("TT0");
    return p ? p->number() : std::nullopt;
}

std::optional<bool> StationModel::fusePresent() const {
    const Parameter *p = parameter("FST");
    return p && p->number() ? std::optional<bool>(*p->number() == 1) : std::nullopt;
}

QString StationModel::triggerAction(const char *code, Confirmation c, qint64 argument) {
    Action *a = action(code);
    if (!a)
        return Tr::tr("%1 does not support %2").arg(displayName(), QString::fromLatin1(code));
    return a->trigger(c, argument);
}

QString StationModel::saveToMemory() {
    Action *nvs = action("NVS");
    if (!nvs)
        return Tr::tr("%1 cannot save to memory").arg(displayName());
    connect(
        nvs, &Action::finished, this,
        [this](bool ok) {
            if (!ok)
                return;
            for (Parameter *p : parameters())
                if (p->meta().savedBy == QLatin1String("NVS"))
                    p->markSaved();
        },
        Qt::SingleShotConnection);
    return nvs->trigger();
}

void StationModel::onParameterChanged(Parameter *p) {
    const CommandSpec &s = p->meta();
    if (s.pattern == QLatin1String("SER") || s.pattern == QLatin1String("PEx") ||
        s.pattern == QLatin1String("TAx") || s.pattern == QLatin1String("PSx"))
        logChange(p, s.usesPort() ? p->spec().port : 0);
}

void StationModel::logChange(Parameter *p, int port) {
    EventLog *log = eventLog();
    const auto v = p->number();
    if (!log || !v)
        return;
    const QByteArray code = p->code();
    const bool first = !m_lastLogged.contains(code);
    const qint64 before = m_lastLogged.value(code, 0);
    m_lastLogged.insert(code, *v);
    if (before == *v && !first)
        return;
    const QString pattern = p->meta().pattern;
    const QString source = sourceName(port);
    if (pattern == QLatin1String("PSx")) {
        if (!first)
            log->add(Event::Kind::Status, Event::Severity::Info, source,
                     Tr::tr("%1 → %2").arg(PortStatus::fromNumber(before).text(),
                                           PortStatus::fromNumber(*v).text()));
    } else if (pattern == QLatin1String("TAx")) {
        if (*v != 0)
            log->add(Event::Kind::Alarm, Event::Severity::Warning, source, p->displayText());
    } else {
        const bool isStation = pattern == QLatin1String("SER");
        const QString table = isStation ? familyInfo().stationErrors : familyInfo().portErrors;
        const int code = isStation ? int(*v) : Catalog::builtin().canonicalPortError(int(*v));
        if (code != 0)
            log->add(isStation ? Event::Kind::StationError : Event::Kind::PortError,
                     severityOf(table, code), source, p->displayText());
        else if (!first)
            log->add(isStation ? Event::Kind::StationError : Event::Kind::PortError,
                     Event::Severity::Info, source, Tr::tr("error cleared"));
    }
}

} // namespace tipscope::model
