#include "discovery.h"

#include "requestqueue.h"

#include "base/elide.h"
#include "protocol/catalog.h"
#include "protocol/datafield.h"

#include <climits>

namespace tipscope::link {

using namespace tipscope::protocol;

QString DeviceInfo::addressText() const {
    return address ? QStringLiteral("%1").arg(*address, 2, 10, QLatin1Char('0'))
                   : QStringLiteral("--");
}

QString DeviceInfo::summary() const {
    return QStringLiteral("%1 %2 %3 %4")
        .arg(addressText(), model, family.isEmpty() ? QStringLiteral("unknown") : family,
             softwareVersion.isEmpty() ? QStringLiteral("-") : softwareVersion);
}

QString IdentifyFailure::text(std::optional<int> address) const {
    switch (kind) {
    case Kind::NoModelNameCommand:
        return Discovery::tr("the catalog names no command that identifies a device");
    case Kind::UnknownModel:
        return Discovery::tr("the device reports the model '%1', which TipScope does not know")
            .arg(base::elided(model));
    case Kind::Unanswered:
        break;
    }
    const QString asked = QString::fromLatin1(command.isEmpty() ? QByteArray("?") : command);
    if (!address)
        return Discovery::tr("the device without addresses did not identify itself (%1): %2")
            .arg(asked, reason);
    return Discovery::tr("the device at address %1 did not identify itself (%2): %3")
        .arg(*address, 2, 10, QLatin1Char('0'))
        .arg(asked, reason);
}

Discovery::Discovery(RequestQueue &queue, QObject *parent)
    : QObject(parent)
    , m_queue(queue) {}

void Discovery::start() {
    const Catalog &cat = Catalog::builtin();
    QList<std::optional<int>> probes;
    const QList<int> factory = {cat.address(QStringLiteral("station")),
                                cat.address(QStringLiteral("feeder")),
                                cat.address(QStringLiteral("extractor"))};
    for (int a : factory)
        probes.append(a);
    if (m_scanAll)
        for (int a = 0; a <= kMaxAddress; ++a)
            if (!factory.contains(a) && a != m_queue.settings().robotAddress)
                probes.append(a);
    probes.append(std::nullopt);
    m_named = false;
    begin(int(probes.size()));
    m_tap = connect(&m_queue.tap(), &FrameTap::event, this, &Discovery::onTap);
    for (int i = 0; i < probes.size(); ++i)
        probe(probes[i], i);
    if (m_outstanding == 0) // no command to probe with
        Q_EMIT finished();
}

void Discovery::identify(std::optional<int> address) {
    m_named = true;
    begin(1);
    probe(address, 0);
    if (m_outstanding == 0) {
        m_identification = identificationOf(std::nullopt);
        Q_EMIT finished();
    }
}

void Discovery::begin(int probes) {
    m_found = QList<std::optional<DeviceInfo>>(probes);
    m_total = probes;
    m_done = 0;
    m_outstanding = 0;
    m_failure.reset();
    m_identification.reset();
    m_statsAtBegin = m_queue.stats();
    m_unanswered.clear();
    m_heardLate.clear();
    m_askedAgain.clear();
    disconnect(m_tap);
}

QString Discovery::whatCameBack() const {
    const LinkStats &now = m_queue.stats();
    QStringList heard;
    for (auto it = now.naks.cbegin(); it != now.naks.cend(); ++it)
        if (const qint64 n = it.value() - m_statsAtBegin.naks.value(it.key()); n > 0)
            heard << tr("%n NAK(s) %1 (%2)", nullptr, int(n))
                         .arg(it.key(), 5, 10, QLatin1Char('0'))
                         .arg(Catalog::builtin().nakText(it.key(), Wording::Translated));
    if (const qint64 n = now.corrupted - m_statsAtBegin.corrupted; n > 0)
        heard << tr("%n answer(s) with a bad block check or format", nullptr, int(n));
    if (const qint64 n = now.stray - m_statsAtBegin.stray; n > 0)
        heard << tr("%n frame(s) from an address not asked", nullptr, int(n));
    if (const qint64 n = now.discardedBytes - m_statsAtBegin.discardedBytes; n > 0)
        heard << tr("%n byte(s) that were no frame", nullptr, int(qMin<qint64>(n, INT_MAX)));
    return heard.join(QLatin1String("; "));
}

std::optional<Request> Discovery::modelNameRequest(std::optional<int> address, bool patient) {
    // Identification comes before the family is known: the first model-name command of any.
    const CommandSpec *modelName = Catalog::builtin().command(Role::ModelName);
    if (!modelName)
        return std::nullopt;
    Request r = Request::read(address, modelName->pattern.toLatin1(), Priority::UserRead);
    if (patient)
        r.minTurnaroundMs = kNamedDeviceTurnaroundMs;
    return r;
}

void Discovery::probe(std::optional<int> address, int slot) {
    std::optional<Request> asked = modelNameRequest(address, m_named);
    if (!asked) {
        m_failure = IdentifyFailure{IdentifyFailure::Kind::NoModelNameCommand, {}, {}, {}, {}};
        return;
    }
    Request &r = *asked;
    m_asked = "R-" + r.command;
    if (!m_named) {
        r.retries = 1; // an absent device costs one timeout more, a noisy line still finds it
        r.probe = true;
    }
    Reply *reply = m_queue.enqueue(r, this);
    ++m_outstanding;
    connect(reply, &Reply::finished, this, [this, reply, address, slot] {
        reply->deleteLater();
        ++m_done;
        Q_EMIT progress(m_done, m_total);
        take(*reply, address, slot);
        if (!m_named && address && reply->error() == ReplyError::Timeout) {
            m_unanswered.insert(*address, slot);
            if (m_heardLate.contains(*address))
                askAgain(*address);
        }
        settle();
    });
}

void Discovery::onTap(const TapEvent &event) {
    if (event.kind != TapEvent::Kind::Decoded || !event.stray || m_outstanding == 0)
        return;
    const protocol::Frame &frame = event.decoded.frame;
    if (!frame.source || "R-" + frame.command != m_asked ||
        (frame.header != Header::Answer && frame.header != Header::Nak))
        return;
    m_heardLate.insert(*frame.source);
    if (m_unanswered.contains(*frame.source))
        askAgain(*frame.source);
}

void Discovery::askAgain(int address) {
    if (m_askedAgain.contains(address))
        return;
    m_askedAgain.insert(address);
    const int slot = m_unanswered.value(address);
    // As patient as with a named device: this one is there, but slower than a search waits.
    const std::optional<Request> r = modelNameRequest(address, true);
    if (!r)
        return;
    Reply *reply = m_queue.enqueue(*r, this);
    ++m_outstanding;
    connect(reply, &Reply::finished, this, [this, reply, address, slot] {
        reply->deleteLater();
        take(*reply, address, slot);
        settle();
    });
}

void Discovery::take(const Reply &reply, std::optional<int> address, int slot) {
    if (!reply.ok() && (m_named || reply.error() != ReplyError::Nak)) {
        m_failure = IdentifyFailure{
            IdentifyFailure::Kind::Unanswered, reply.error(), reply.errorString(), {}, m_asked};
        return;
    }
    // In a search a NAK is an answer too: something lives at this address.
    DeviceInfo d;
    d.address = address;
    if (reply.ok()) {
        d.model = QString::fromLatin1(reply.answer().data).trimmed();
        d.family = Catalog::builtin().familyForModel(d.model);
    }
    m_found[slot] = d;
    if (d.family.isEmpty())
        return;
    if (const auto version =
            Catalog::builtin().resolve(d.family, Role::SoftwareVersion, 0, Direction::Read))
        askVersion(slot, *version);
}

void Discovery::askVersion(int slot, const protocol::ResolvedCommand &version) {
    Request r = Request::read(m_found[slot]->address, version);
    const std::optional<int> address = m_found[slot]->address;
    if (m_named || (address && m_askedAgain.contains(*address)))
        r.minTurnaroundMs = kNamedDeviceTurnaroundMs;
    Reply *reply = m_queue.enqueue(r, this);
    ++m_outstanding;
    connect(reply, &Reply::finished, this, [this, reply, slot] {
        reply->deleteLater();
        if (reply->ok())
            m_found[slot]->softwareVersion = QString::fromLatin1(reply->answer().data).trimmed();
        settle();
    });
}

void Discovery::settle() {
    if (--m_outstanding > 0)
        return;
    disconnect(m_tap);
    if (m_named)
        m_identification = identificationOf(m_found.value(0));
    for (const auto &d : m_found)
        if (d)
            Q_EMIT deviceFound(*d);
    Q_EMIT finished();
}

Identification Discovery::identificationOf(const std::optional<DeviceInfo> &found) const {
    if (!found)
        return base::failure(*m_failure);
    if (found->family.isEmpty())
        return base::failure(
            IdentifyFailure{IdentifyFailure::Kind::UnknownModel, {}, {}, found->model, m_asked});
    return *found;
}

QList<DeviceInfo> Discovery::devices() const {
    QList<DeviceInfo> out;
    for (const auto &d : m_found)
        if (d)
            out.append(*d);
    return out;
}

} // namespace tipscope::link
