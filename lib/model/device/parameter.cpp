#include "parameter.h"

#include "devicemodel.h"
#include "settingname.h"
#include "writeproof.h"

#include <QCoreApplication>
#include <QTimer>

namespace tipscope::model {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {
struct ParameterTr {
    Q_DECLARE_TR_FUNCTIONS(Parameter)
};
constexpr double kRateSmoothing = 0.2;
} // namespace

Parameter::Parameter(DeviceModel &device, std::optional<ResolvedCommand> read,
                     std::optional<ResolvedCommand> write, QObject *parent)
    : QObject(parent)
    , m_device(device)
    , m_read(std::move(read))
    , m_write(std::move(write)) {
    Q_ASSERT(m_read || m_write);
}

const ResolvedCommand &Parameter::spec() const {
    return m_write ? *m_write : *m_read;
}

std::optional<qint64> Parameter::number() const {
    if (!m_value || m_value->isText)
        return std::nullopt;
    return m_value->number;
}

qint64 Parameter::minimum() const {
    qint64 lo = spec().min;
    if (m_lower && m_lower->number())
        lo = qMax(lo, *m_lower->number());
    return lo;
}

qint64 Parameter::maximum() const {
    qint64 hi = spec().max;
    if (m_upper && m_upper->number())
        hi = qMin(hi, *m_upper->number());
    return hi;
}

void Parameter::setLimitParameters(Parameter *lower, Parameter *upper) {
    m_lower = lower;
    m_upper = upper;
}

QString Parameter::allowedText() const {
    if (!m_write)
        return ParameterTr::tr("read-only");
    const ResolvedCommand &c = *m_write;
    if (c.spec->kind != ValueKind::Number && c.spec->kind != ValueKind::Delay)
        return protocol::allowedText(c);
    const TemperatureUnit t = m_device.temperatureUnit();
    QString text = ParameterTr::tr("%1 to %2")
                       .arg(formatNumber(c, minimum(), t), formatNumber(c, maximum(), t));
    if (c.spec->step > 1) {
        const DisplayFormat f = displayFormat(c, t);
        text += ParameterTr::tr(" in steps of %1 %2")
                    .arg(QLocale().toString(c.spec->step * f.scale, 'f', f.decimals), f.unit);
    }
    QStringList specials;
    for (const QString &s : c.spec->special)
        specials.append(catalogText(s));
    if (!specials.isEmpty())
        text += ParameterTr::tr(", or %1").arg(specials.join(QLatin1String(", ")));
    return text;
}

QString Parameter::validate(qint64 wire) const {
    if (!m_write)
        return ParameterTr::tr("%1 cannot be written").arg(label());
    const ResolvedCommand &c = *m_write;
    const bool special = c.spec->special.contains(int(wire));
    const bool numeric = c.spec->kind == ValueKind::Number || c.spec->kind == ValueKind::Delay;
    const bool inside = !numeric || special || (wire >= minimum() && wire <= maximum());
    if (protocol::validate(c, wire).isEmpty() && inside)
        return {};
    const QString shown = numeric && !special ? formatNumber(c, wire, m_device.temperatureUnit())
                                              : QString::number(wire);
    return ParameterTr::tr("%1 is not allowed for %2: allowed is %3")
        .arg(shown, label(), allowedText());
}

QString Parameter::displayText() const {
    if (!m_value)
        return ParameterTr::tr("—");
    return formatValue(spec(), *m_value, m_device.temperatureUnit());
}

QString Parameter::setEdit(qint64 wire) {
    if (m_device.writesBlocked())
        return ParameterTr::tr("monitor-only mode is on: nothing is written");
    const QString why = validate(wire);
    if (!why.isEmpty())
        return why;
    m_edit = wire;
    Q_EMIT editChanged();
    setState(m_value && m_value->number == wire && !m_value->isText ? State::InSync
                                                                    : State::Edited);
    if (m_state == State::InSync)
        m_edit.reset();
    return {};
}

QString Parameter::setEditText(const QString &text) {
    if (!m_write)
        return ParameterTr::tr("%1 cannot be written").arg(label());
    const auto wire = parseDisplayText(*m_write, text, m_device.temperatureUnit());
    if (!wire)
        return ParameterTr::tr("%1: %2; allowed is %3").arg(label(), wire.error(), allowedText());
    return setEdit(*wire);
}

void Parameter::revert() {
    if (!m_edit)
        return;
    m_edit.reset();
    Q_EMIT editChanged();
    setState(m_value ? State::InSync : State::Unknown);
}

bool Parameter::isCurrent() const {
    return m_value.has_value() && m_device.isLineUp();
}

void Parameter::setState(State s, const QString &failure) {
    if (s != State::Failed)
        m_failedByLine = false;
    if (s == m_state && failure == m_failure)
        return;
    m_state = s;
    m_failure = failure;
    Q_EMIT stateChanged();
}

Reply *Parameter::refresh(Priority priority) {
    if (!m_read)
        return nullptr;
    // A read that fails must not turn a failed write into "in sync": it goes back to the failure.
    const bool wasFailed = m_state == State::Failed;
    const QString failure = m_failure;
    const bool byLine = m_failedByLine;
    if (m_state == State::Unknown || m_state == State::Failed)
        setState(State::Reading);
    Reply *reply =
        m_device.queue().enqueue(Request::read(m_device.address(), *m_read, priority), this);
    reply->setDeleteWhenFinished(true);
    connect(reply, &Reply::finished, this, [this, reply, wasFailed, failure, byLine] {
        if (reply->ok()) {
            deviceReported(reply->answer().data, double(reply->answerAgeUs()) / 1000);
            return;
        }
        if (m_state == State::Reading && wasFailed) {
            setState(State::Failed, failure);
            m_failedByLine = byLine;
        } else if (m_state == State::Reading) {
            setState(m_value ? State::InSync : State::Unknown);
        }
        m_lastReadFailed = true;
        Q_EMIT readFailed();
        // A refusal is said once, when it begins: the scheduler asks again only now and then,
        // and the same answer each time is no news.
        if (reply->error() == link::ReplyError::Nak) {
            if (m_refusal == reply->errorString())
                return;
            m_refusal = reply->errorString();
            Q_EMIT refusalChanged();
        }
        m_device.logCommunication(
            ParameterTr::tr("reading %1 (%2)").arg(settingName(*this), QString::fromLatin1(code())),
            reply->errorString());
    });
    return reply;
}

void Parameter::deviceReported(const QByteArray &data, double ageMs) {
    if (!m_read)
        return;
    m_reportedAgeMs = ageMs;
    const auto v = decodeAnswer(*m_read, data);
    if (!v) {
        m_device.logCommunication(
            ParameterTr::tr("reading %1").arg(settingName(*this)),
            ParameterTr::tr("unreadable data field '%1'").arg(QString::fromLatin1(data)));
        return;
    }
    // Milliseconds, not a QDateTime: a local date and time looks up the time zone each time,
    // which at live polling rates was a visible share of the GUI's CPU.
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    if (m_lastUpdateMs >= 0) {
        const double dt = double(now - m_lastUpdateMs) / 1000.0;
        if (dt > 0)
            m_rateHz = m_rateHz == 0 ? 1.0 / dt : m_rateHz + kRateSmoothing * (1.0 / dt - m_rateHz);
    }
    m_lastUpdateMs = now;
    m_lastReadFailed = false;
    if (isRefused()) {
        m_refusal.clear();
        Q_EMIT refusalChanged();
    }
    const bool changed = !m_value || !(*m_value == *v);
    m_value = v;
    m_raw = data;
    if (m_state == State::Unknown || m_state == State::Reading)
        setState(m_edit ? State::Edited : State::InSync);
    Q_EMIT updated();
    if (changed) {
        Q_EMIT valueChanged();
        Q_EMIT m_device.parameterChanged(this);
    }
}

quint64 Parameter::apply() {
    if (!m_edit || !m_write || m_runningWrite != 0)
        return 0;
    static quint64 lastWriteId = 0;
    const quint64 id = ++lastWriteId;
    m_runningWrite = id;
    const QString blocked = m_device.writesBlocked()
                                ? ParameterTr::tr("monitor-only mode is on: nothing is written")
                                : validate(*m_edit);
    const auto data = blocked.isEmpty() ? encodeWrite(*m_write, *m_edit)
                                        : base::Outcome<QByteArray>(base::failure(blocked));
    if (!data) {
        const QString why = data.error();
        // The caller learns the id from this call: tell the outcome once it can listen.
        QTimer::singleShot(0, this, [this, why, id] { fail(why, id); });
        return id;
    }
    setState(State::Writing);
    const bool repeatable = !meta().dangerous;
    Reply *reply = m_device.queue().enqueue(
        Request::write(m_device.address(), code(), *data, repeatable), this);
    connect(reply, &Reply::finished, this, [this, reply, data = *data, id] {
        reply->deleteLater();
        if (!reply->ok()) {
            // Only a refusal or a closed line proves nothing was written; when the answer was
            // lost the device may hold the new value, so say so and look.
            const ReplyError e = reply->error();
            const bool byLine = e == ReplyError::NotOpen || e == ReplyError::Disconnected;
            if (e == ReplyError::Nak || e == ReplyError::NotOpen || e == ReplyError::Cancelled) {
                fail(ParameterTr::tr("not written: %1").arg(reply->errorString()), id, byLine);
                return;
            }
            fail(ParameterTr::tr("perhaps not written, the answer was lost: %1")
                     .arg(reply->errorString()),
                 id, byLine);
            refresh();
            return;
        }
        if (m_read) {
            readBack(data, id);
            return;
        }
        m_edit.reset();
        setState(State::InSync);
        succeed(id);
    });
    return id;
}

void Parameter::readBack(const QByteArray &written, quint64 id) {
    WriteProof *proof =
        WriteProof::start(m_device.queue(), m_device.address(), *m_read, written, this);
    connect(proof, &WriteProof::finished, this, [this, written, id](const WriteProof::Result &r) {
        if (r.error != ReplyError::None) {
            fail(ParameterTr::tr("written, but the read-back failed: %1").arg(r.errorString), id,
                 r.error == ReplyError::NotOpen || r.error == ReplyError::Disconnected);
            return;
        }
        const auto wrote = decodeAnswer(*m_read, written);
        deviceReported(r.reported, r.ageMs);
        if (!r.confirmed) {
            fail(ParameterTr::tr("the device reports %1 after %2 was written")
                     .arg(displayText(), formatValue(*m_read, wrote.value_or(Value()),
                                                     m_device.temperatureUnit())),
                 id);
            return;
        }
        m_edit.reset();
        m_unsavedWrite = meta().isVolatile;
        Q_EMIT editChanged();
        setState(State::InSync);
        Q_EMIT stateChanged(); // isSavedToMemory() changed even if the state did not
        // For audit: what was written and that the read-back proved it.
        m_device.logWrite(spec().port,
                          ParameterTr::tr("%1 set to %2")
                              .arg(settingName(*this, NameParts::ToolOnly), displayText()),
                          {{QStringLiteral("code"), QString::fromLatin1(code())},
                           {QStringLiteral("value"), displayText()},
                           {QStringLiteral("readBack"), QStringLiteral("confirmed")}});
        succeed(id);
    });
}

void Parameter::succeed(quint64 id) {
    m_runningWrite = 0;
    Q_EMIT writeFinished(true, {}, id);
}

void Parameter::fail(const QString &reason, quint64 id, bool byLine) {
    m_runningWrite = 0;
    setState(State::Failed, reason);
    m_failedByLine = byLine;
    m_device.logCommunication(ParameterTr::tr("writing %1").arg(settingName(*this)), reason);
    Q_EMIT writeFinished(false, reason, id);
}

bool Parameter::isSavedToMemory() const {
    return !meta().isVolatile || !m_unsavedWrite;
}

void Parameter::lineRestored() {
    if (m_state != State::Failed || !m_failedByLine)
        return;
    setState(m_edit ? State::Edited : m_value ? State::InSync : State::Unknown);
    refresh(Priority::Background);
}

void Parameter::markSaved() {
    m_unsavedWrite = false;
    Q_EMIT stateChanged();
}

} // namespace tipscope::model
