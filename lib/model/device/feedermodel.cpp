#include "feedermodel.h"

#include "model/events/eventlog.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct FeederModelTr {
    Q_DECLARE_TR_FUNCTIONS(FeederModel)
};

QList<Parameter *> writable(const QList<Parameter *> &params, bool wanted) {
    QList<Parameter *> out;
    for (Parameter *p : params)
        if (p->isWritable() == wanted)
            out.append(p);
    return out;
}
} // namespace

FeederModel::FeederModel(link::RequestQueue &queue, const link::DeviceInfo &info, QObject *parent)
    : FeederModel(queue, info, Catalog::builtin(), parent) {}

FeederModel::FeederModel(link::RequestQueue &queue, const link::DeviceInfo &info,
                         const Catalog &catalog, QObject *parent)
    : DeviceModel(queue, info, catalog, parent) {}

QList<Parameter *> FeederModel::settings() const {
    return writable(parameters(Group::Feeder), true);
}

QList<Parameter *> FeederModel::counters() const {
    return parameters(Group::Counter);
}

QList<FeederModel::CounterRow> FeederModel::counterRows() const {
    QList<CounterRow> rows;
    QStringList keys;
    for (Parameter *p : counters()) {
        const CommandSpec &s = p->meta();
        const QString key = s.quantity.isEmpty() ? s.name : s.quantity;
        if (!keys.contains(key)) {
            keys.append(key);
            rows.append(CounterRow{key, nullptr, nullptr, nullptr});
        }
        CounterRow &row = rows[keys.indexOf(key)];
        (s.partial ? row.partial : row.total) = p;
        if (s.partial)
            row.reset = action(p->code());
    }
    return rows;
}

QList<Parameter *> FeederModel::liveParameters() const {
    return writable(parameters(Group::Feeder), false);
}

std::optional<bool> FeederModel::isFeeding() const {
    const auto v = number(Role::Feeding);
    return v ? std::optional<bool>(*v == 1) : std::nullopt;
}

std::optional<qint64> FeederModel::fedLength() const {
    return number(Role::FedLength);
}

std::optional<qint64> FeederModel::feedSpeed() const {
    return number(Role::FeedSpeed);
}

std::optional<int> FeederModel::errorCode() const {
    const auto v = number(Role::Error);
    return v ? std::optional<int>(int(*v)) : std::nullopt;
}

QString FeederModel::errorText() const {
    const auto e = errorCode();
    return e ? catalog().feederErrorText(*e, Wording::Translated) : FeederModelTr::tr("—");
}

Level FeederModel::errorLevel() const {
    const Parameter *p = parameter(Role::Error);
    return p ? levelOf(catalog(), p->meta().table, errorCode()) : Level::Unknown;
}

QString FeederModel::resetPartialCounter(const QByteArray &code, Confirmation c) {
    return trigger(action(code), QString::fromLatin1(code), c, 0);
}

QString FeederModel::trigger(Role role, Confirmation c, qint64 arg) {
    return trigger(action(role), commandName(role), c, arg);
}

QString FeederModel::trigger(Action *action, const QString &name, Confirmation c, qint64 arg) {
    if (!action)
        return FeederModelTr::tr("%1 has no command %2").arg(displayName(), name);
    return action->trigger(c, arg);
}

void FeederModel::onParameterChanged(Parameter *p) {
    if (p->meta().role != Role::Error || !eventLog() || !p->number())
        return;
    const qint64 v = *p->number();
    const bool first = !m_lastError.has_value();
    if (!first && *m_lastError == v)
        return;
    m_lastError = v;
    if (v != 0)
        logEvent(Event::Kind::FeederError, Event::Severity::Error, 0, errorText());
    else if (!first)
        logEvent(Event::Kind::FeederError, Event::Severity::Info, 0,
                 FeederModelTr::tr("error cleared"));
}

} // namespace tipscope::model
