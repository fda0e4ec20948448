#include "wireuse.h"

#include "jointscore.h"
#include "link/line.h"
#include "model/live/pollscheduler.h"

#include <algorithm>

namespace tipscope::bench {

using namespace tipscope::model;

WireUse::WireUse(link::Line &line, StationModel &station, const PollScheduler &scheduler,
                 double bytesPerSecond)
    : m_line(line)
    , m_station(station)
    , m_scheduler(scheduler)
    , m_bytesPerSecond(bytesPerSecond) {
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, &WireUse::tick);
    for (Parameter *p : station.parameters()) {
        const qsizetype index = m_reads.size();
        const int port = p->meta().usesPort() ? p->spec().port : 0;
        m_reads.append({p->meta().pattern, port, p->meta().role, 0});
        // Refused or unanswered reads took the wire too.
        const auto count = [this, index] { ++m_reads[index].sinceTick; };
        connect(p, &Parameter::updated, this, count);
        connect(p, &Parameter::readFailed, this, count);
    }
}

void WireUse::start() {
    const link::LinkStats &s = m_line.queue().stats();
    m_lastAnswered = s.answered;
    m_lastBytes = s.sentBytes + s.receivedBytes;
    for (Reads &r : m_reads)
        r.sinceTick = 0;
    m_busy.fill(false);
    m_tick.start();
}

void WireUse::tick() {
    const link::LinkStats &s = m_line.queue().stats();
    const qint64 answered = s.answered - m_lastAnswered;
    const qint64 bytes = s.sentBytes + s.receivedBytes - m_lastBytes;
    m_lastAnswered = s.answered;
    m_lastBytes = s.sentBytes + s.receivedBytes;
    const bool anyBusy = std::find(m_busy.begin(), m_busy.end(), true) != m_busy.end();
    for (Reads &r : m_reads) {
        if (anyBusy && r.sinceTick > 0) {
            const bool portBusy =
                r.port > 0 && r.port < int(m_busy.size()) && m_busy[size_t(r.port)];
            const bool tip = r.role == protocol::Role::TipTemperature;
            const bool power = r.role == protocol::Role::Power;
            const QString kind =
                tip || power
                    ? QStringLiteral("%1 of a %2 port")
                          .arg(tip ? QStringLiteral("tip") : QStringLiteral("power"),
                               portBusy ? QStringLiteral("busy") : QStringLiteral("resting"))
                    : r.kind;
            m_busyReadsByKind[kind] += r.sinceTick;
            if (tip && portBusy)
                m_busyTipReads += r.sinceTick;
        }
        r.sinceTick = 0;
    }
    if (anyBusy) {
        ++m_busyTicks;
        m_busyAnswered += answered;
        m_busyBytes += bytes;
    }
    for (size_t port = 1; port < m_busy.size(); ++port)
        m_busy[port] = m_scheduler.isBusy(&m_station, int(port));
}

QList<JointFigure> WireUse::figures() const {
    const double seconds = double(m_busyTicks * kTickMs) / 1000;
    const double rate = seconds > 0 ? double(m_busyAnswered) / seconds : 0;
    const double limit =
        m_busyBytes > 0 ? m_bytesPerSecond * double(m_busyAnswered) / double(m_busyBytes) : 0;
    return {
        {QStringLiteral("busy_seconds"), seconds, QStringLiteral("s"), 0},
        {QStringLiteral("busy_tx_per_s"), rate, QStringLiteral("tx/s"), 1},
        {QStringLiteral("busy_wire_ratio"), limit > 0 ? rate / limit : 0, QString(), 3},
        {QStringLiteral("busy_tip_share"),
         m_busyAnswered > 0 ? double(m_busyTipReads) / double(m_busyAnswered) : 0, QString(), 3},
    };
}

QString WireUse::breakdown() const {
    qint64 all = 0;
    QList<std::pair<qint64, QString>> kinds;
    for (auto it = m_busyReadsByKind.begin(); it != m_busyReadsByKind.end(); ++it) {
        all += it.value();
        kinds.append({it.value(), it.key()});
    }
    std::sort(kinds.begin(), kinds.end(), [](const auto &a, const auto &b) { return a > b; });
    QStringList parts;
    for (const auto &[reads, kind] : kinds)
        parts << QStringLiteral("%1 %2 %").arg(kind).arg(100.0 * double(reads) / double(all), 0,
                                                         'f', 1);
    return parts.join(QStringLiteral(", "));
}

} // namespace tipscope::bench
