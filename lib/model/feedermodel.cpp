#include "feedermodel.h"

#include "eventlog.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(FeederModel)
};

QList<Parameter *> pick(const DeviceModel &d, std::initializer_list<const char *> codes) {
    QList<Parameter *> out;
    for (const char *c : codes)
        if (Parameter *p = d.parameter(c))
            out.append(p);
    return out;
}
} // namespace

FeederModel::FeederModel(link::RequestQueue &queue, const link::DeviceInfo &info, QObject *parent)
    : DeviceModel(queue, info, parent) {}

QList<Parameter *> FeederModel::settings() const {
    return pick(*this, {"MOD", "SPD", "LEN", "THI", "TES"});
}

QList<Parameter *> FeederModel::counters() const {
    return pick(*this, {"CPT", "CPP", "CFT", "CFP", "CTT", "CTP"});
}

QList<Parameter *> FeederModel::liveParameters() const {
    return pick(*this, {"FDS", "FDL"});
}

std::optional<bool> FeederModel::isFeeding() const {
    const Parameter *p = parameter("FDS");
    return p && p->number() ? std::optional<bool>(*p->number() == 1) : std::nullopt;
}

std::optional<qint64> FeederModel::fedLength() const {
    const Parameter *p = parameter("FDL");
    return p ? p->number() : std::nullopt;
}

std::optional<int> FeederModel::errorCode() const {
    const Parameter *p = parameter("ECV");
    return p && p->number() ? std::optional<int>(int(*p->number())) : std::nullopt;
}

QString FeederModel::errorText() const {
    const auto e = errorCode();
    return e ? Catalog::builtin().feederErrorText(*e, Wording::Translated) : Tr::tr("—");
}

QString FeederModel::trigger(const QByteArray &code, Confirmation c, qint64 arg) {
    Action *a = action(code);
    if (!a)
        return Tr::tr("%1 has no command %2").arg(displayName(), QString::fromLatin1(code));
    return a->trigger(c, arg);
}

void FeederModel::onParameterChanged(Parameter *p) {
    if (p->code() != "ECV" || !eventLog() || !p->number())
        return;
    const qint64 v = *p->number();
    const bool first = !m_lastError.has_value();
    if (!first && *m_lastError == v)
        return;
    m_lastError = v;
    if (v != 0)
        eventLog()->add(Event::Kind::FeederError, Event::Severity::Error, displayName(),
                        errorText());
    else if (!first)
        eventLog()->add(Event::Kind::FeederError, Event::Severity::Info, displayName(),
                        Tr::tr("error cleared"));
}

} // namespace tipscope::model
