#include "discovery.h"

#include "requestqueue.h"

#include "protocol/catalog.h"
#include "protocol/datafield.h"

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

Discovery::Discovery(RequestQueue &queue, QObject *parent)
    : QObject(parent)
    , m_queue(queue) {}

void Discovery::start() {
    const Catalog &cat = Catalog::builtin();
    QList<std::optional<int>> probes;
    if (m_mode != Mode::Unaddressed) {
        const QList<int> factory = {cat.address(QStringLiteral("station")),
                                    cat.address(QStringLiteral("feeder")),
                                    cat.address(QStringLiteral("extractor"))};
        for (int a : factory)
            probes.append(a);
        if (m_scanAll)
            for (int a = 0; a <= kMaxAddress; ++a)
                if (!factory.contains(a) && a != m_queue.settings().robotAddress)
                    probes.append(a);
    }
    if (m_mode != Mode::Addressed)
        probes.append(std::nullopt);
    m_found = QList<std::optional<DeviceInfo>>(probes.size());
    m_total = int(probes.size());
    m_done = 0;
    m_outstanding = 0;
    for (int i = 0; i < probes.size(); ++i)
        probe(probes[i], i);
}

void Discovery::probe(std::optional<int> address, int slot) {
    Request r = Request::read(address, "SMN", Priority::UserRead);
    r.retries = 1; // an absent device costs one timeout more, a noisy line still finds devices
    r.probe = true;
    Reply *reply = m_queue.enqueue(r, this);
    ++m_outstanding;
    connect(reply, &Reply::finished, this, [this, reply, address, slot] {
        reply->deleteLater();
        ++m_done;
        Q_EMIT progress(m_done, m_total);
        if (reply->ok() || reply->error() == ReplyError::Nak) {
            // A NAK is an answer too: something lives at this address.
            DeviceInfo d;
            d.address = address;
            if (reply->ok()) {
                d.model = QString::fromLatin1(reply->answer().data).trimmed();
                d.family = Catalog::builtin().familyForModel(d.model);
            }
            m_found[slot] = d;
            if (!d.family.isEmpty() &&
                Catalog::builtin().resolve(d.family, "SVR", Direction::Read)) {
                identify(slot);
            }
        }
        settle();
    });
}

void Discovery::identify(int slot) {
    Reply *reply = m_queue.enqueue(Request::read(m_found[slot]->address, "SVR"), this);
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
    for (const auto &d : m_found)
        if (d)
            Q_EMIT deviceFound(*d);
    Q_EMIT finished();
}

QList<DeviceInfo> Discovery::devices() const {
    QList<DeviceInfo> out;
    for (const auto &d : m_found)
        if (d)
            out.append(*d);
    return out;
}

} // namespace tipscope::link
