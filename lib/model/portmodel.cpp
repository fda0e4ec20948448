#include "portmodel.h"

#include "stationmodel.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(PortModel)
};
const char *const kCounterBases[] = {"CP", "CW", "CS", "CH", "CN", "CC", "CD"};
} // namespace

PortStatus PortStatus::fromNumber(qint64 v) {
    PortStatus s;
    s.mode = Mode(qBound(qint64(0), v % 10, qint64(3)));
    s.cooling = (v / 10) % 10 == 1;
    s.suction = (v / 100) % 10 == 1;
    s.motor = int((v / 1000) % 10);
    return s;
}

QString PortStatus::modeName(Mode mode) {
    switch (mode) {
    case Mode::Working:
        return Tr::tr("Working");
    case Mode::Stand:
        return Tr::tr("Stand");
    case Mode::Sleep:
        return Tr::tr("Sleep");
    case Mode::Hibernation:
        return Tr::tr("Hibernation");
    }
    return {};
}

QString PortStatus::text() const {
    QStringList parts{modeName(mode)};
    if (cooling)
        parts.append(Tr::tr("Cooling"));
    if (suction)
        parts.append(Tr::tr("Suction"));
    if (motor == 1)
        parts.append(Tr::tr("Motor forward"));
    else if (motor == 2)
        parts.append(Tr::tr("Motor backward"));
    return parts.join(QLatin1String(", "));
}

PortModel::PortModel(StationModel &station, int port, QObject *parent)
    : QObject(parent)
    , m_station(station)
    , m_port(port) {
    const QByteArray suffix = QByteArray::number(port);
    for (Parameter *p : station.parameters()) {
        const QByteArray code = p->code();
        const bool ofThisPort =
            p->meta().usesPort() &&
            code.at(p->meta().pattern.indexOf(QLatin1Char('x'))) == suffix.at(0);
        if (ofThisPort)
            connect(p, &Parameter::valueChanged, this, &PortModel::changed);
    }
}

Parameter *PortModel::param(const char *base) const {
    return m_station.parameter(QByteArray(base) + QByteArray::number(m_port));
}

static std::optional<qint64> numberOf(const Parameter *p) {
    return p ? p->number() : std::nullopt;
}

std::optional<qint64> PortModel::tipTemperature() const {
    return numberOf(param("TT"));
}
std::optional<qint64> PortModel::selectedTemperature() const {
    return numberOf(param("ST"));
}
std::optional<qint64> PortModel::power() const {
    return numberOf(param("PP"));
}

std::optional<PortStatus> PortModel::status() const {
    const auto v = numberOf(param("PS"));
    return v ? std::optional<PortStatus>(PortStatus::fromNumber(*v)) : std::nullopt;
}

std::optional<int> PortModel::tool() const {
    const auto v = numberOf(param("CT"));
    return v ? std::optional<int>(int(*v)) : std::nullopt;
}

QString PortModel::toolName() const {
    const auto t = tool();
    if (!t)
        return Tr::tr("—");
    const QMap<int, QString> tools =
        Catalog::builtin().table(QStringLiteral("$toolTable"), m_station.family());
    return tools.contains(*t) ? catalogText(tools.value(*t)) : Tr::tr("tool %1").arg(*t);
}

std::optional<int> PortModel::error() const {
    const auto v = numberOf(param("PE"));
    return v ? std::optional<int>(Catalog::builtin().canonicalPortError(int(*v))) : std::nullopt;
}

QString PortModel::errorText() const {
    const auto e = error();
    return e ? Catalog::builtin().portErrorText(m_station.family(), *e, Wording::Translated)
             : Tr::tr("—");
}

int PortModel::alarmFlags() const {
    return int(numberOf(param("TA")).value_or(0));
}

QList<int> PortModel::toolOrder() const {
    QList<int> order = m_station.familyInfo().tools;
    if (const auto t = tool(); t && order.contains(*t)) {
        order.removeAll(*t);
        order.prepend(*t);
    }
    return order;
}

QList<Parameter *> PortModel::toolSettings(int tool) const {
    QList<Parameter *> out;
    for (char letter : {'A', 'S', 'D', 'H'})
        if (Parameter *p = m_station.parameter(QByteArray(1, letter) + QByteArray::number(m_port) +
                                               QByteArray::number(tool)))
            out.append(p);
    return out;
}

static QList<Parameter *> existing(const PortModel &port,
                                   std::initializer_list<const char *> bases) {
    QList<Parameter *> out;
    for (const char *b : bases)
        if (Parameter *p = port.param(b))
            out.append(p);
    return out;
}

QList<Parameter *> PortModel::alarmSettings() const {
    return existing(*this, {"HA", "LA", "HD", "LD"});
}

QList<Parameter *> PortModel::counters() const {
    QList<Parameter *> out;
    for (const char *b : kCounterBases)
        if (Parameter *p = param(b))
            out.append(p);
    return out;
}

QList<Parameter *> PortModel::liveParameters() const {
    return existing(*this, {"TT", "PP", "PS", "ST"});
}

QList<Parameter *> PortModel::statusParameters() const {
    return existing(*this, {"CT", "PE", "TA", "ED", "QT"});
}

QString PortModel::setMode(int writeValue) {
    Parameter *ps = param("PS");
    if (!ps)
        return Tr::tr("this port has no status command");
    const QString why = ps->setEdit(writeValue);
    if (why.isEmpty())
        ps->apply();
    return why;
}

QString PortModel::setSelectedTemperature(qint64 celsius) {
    Parameter *st = param("ST");
    const QString why = st->setEdit(celsius);
    if (why.isEmpty())
        st->apply();
    return why;
}

} // namespace tipscope::model
