#include "soakwriter.h"

#include "model/device/stationmodel.h"

#include <QTimer>

namespace tipscope::bench {

using model::Parameter;

namespace {
constexpr int kExamples = 5;
constexpr int kMaxPauseMs = 100; // between a finished write and the next, like a person clicking
} // namespace

WriteStream::WriteStream(model::StationModel &station, const QList<QByteArray> &codes, quint32 seed,
                         DeviceProbe probe, QObject *parent)
    : QObject(parent)
    , m_probe(std::move(probe))
    , m_rng(seed) {
    m_clock.start();
    for (const QByteArray &code : codes) {
        Parameter *p = station.parameter(code);
        if (!p || !p->isWritable())
            continue;
        m_tracks[code].parameter = p;
        connect(p, &Parameter::writeFinished, this, &WriteStream::onFinished);
    }
}

void WriteStream::setInitial(const QByteArray &code, qint64 value) {
    if (m_tracks.contains(code))
        m_tracks[code].lastVerified = value;
}

void WriteStream::start(int inFlight) {
    m_inFlightTarget = inFlight;
    m_issuing = true;
    for (int i = 0; i < inFlight; ++i)
        issueNext();
}

qint64 WriteStream::pickValue(const Track &t) {
    const Parameter &p = *t.parameter;
    const qint64 step = qMax(1, p.meta().step);
    const qint64 lo = p.minimum();
    const qint64 steps = (p.maximum() - lo) / step;
    // Not what the device is believed to hold, and not what is shown: a failed write may have
    // reached the device, and setting the shown value leaves nothing to write.
    const QList<std::optional<qint64>> avoid{t.lastVerified, p.number()};
    for (;;) {
        const qint64 v = lo + step * qint64(m_rng.bounded(quint32(steps + 1)));
        if (!avoid.contains(v))
            return v;
    }
}

void WriteStream::issueNext() {
    if (!m_issuing || m_inFlight >= m_inFlightTarget)
        return;
    // A parameter with no write or check under way, chosen at random so every code sees traffic.
    QList<QByteArray> idle;
    for (auto it = m_tracks.cbegin(); it != m_tracks.cend(); ++it)
        if (!it->busy && it->parameter)
            idle.append(it.key());
    if (idle.isEmpty())
        return;
    const QByteArray code = idle.at(int(m_rng.bounded(quint32(idle.size()))));
    Track &t = m_tracks[code];
    const qint64 value = pickValue(t);
    if (const QString why = t.parameter->setEdit(value); !why.isEmpty()) {
        ++m_tally.refused;
        if (m_tally.examples.size() < kExamples)
            m_tally.examples.append(QStringLiteral("%1 refused: %2").arg(code, why));
        scheduleNext();
        return;
    }
    const quint64 id = t.parameter->apply();
    if (id == 0) {
        ++m_tally.notStarted;
        if (m_tally.examples.size() < kExamples)
            m_tally.examples.append(QStringLiteral("%1 = %2: apply() started no write (%3)")
                                        .arg(QString::fromLatin1(code))
                                        .arg(value)
                                        .arg(int(t.parameter->state())));
        scheduleNext();
        return;
    }
    t.busy = true;
    ++m_inFlight;
    ++m_tally.issued;
    m_open.insert(id, {code, value, m_clock.elapsed()});
}

void WriteStream::scheduleNext() {
    QTimer::singleShot(int(m_rng.bounded(kMaxPauseMs + 1)), this, &WriteStream::issueNext);
}

void WriteStream::onFinished(bool ok, const QString &reason, quint64 id) {
    if (!m_open.contains(id)) {
        ++(m_finished.contains(id) ? m_tally.reportedTwice : m_tally.unsolicited);
        return;
    }
    const OpenWrite w = m_open.take(id);
    m_finished.insert(id);
    Track &t = m_tracks[w.code];
    if (ok) {
        ++m_tally.verified;
        m_tally.verifiedMs.append(double(m_clock.elapsed() - w.startedMs));
        t.lastVerified = w.value;
        t.failedSince.clear();
    } else {
        ++m_tally.failed;
        ++m_tally.failedBy[classify(reason)];
        if (m_tally.examples.size() < kExamples)
            m_tally.examples.append(QStringLiteral("%1: %2").arg(w.code, reason));
        t.failedSince.append({w.value, reason});
    }
    checkDevice(w.code, ok ? std::optional<qint64>(w.value) : std::nullopt);
}

void WriteStream::checkDevice(const QByteArray &code, std::optional<qint64> exactly) {
    m_probe(code,
            [this, code, exactly](std::optional<qint64> held) { checked(code, exactly, held); });
}

void WriteStream::checked(const QByteArray &code, std::optional<qint64> exactly,
                          std::optional<qint64> held) {
    ++m_tally.deviceChecks;
    const bool fits =
        held && (exactly ? *held == *exactly : judge(code, *held) != Verdict::Unexpected);
    if (!fits) {
        ++m_tally.deviceMismatches;
        if (m_tally.mismatches.size() < kExamples)
            m_tally.mismatches.append(
                QStringLiteral("%1 holds %2 after a write ended; %3")
                    .arg(QString::fromLatin1(code),
                         held ? QString::number(*held) : QStringLiteral("nothing readable"),
                         exactly ? QStringLiteral("verified %1").arg(*exactly)
                                 : expectationText(code)));
    }
    m_tracks[code].busy = false;
    --m_inFlight;
    scheduleNext();
}

QString WriteStream::classify(const QString &reason) {
    // Read-back first: "written, but the read-back failed: no answer" is not a lost write.
    static const QList<QPair<const char *, QLatin1String>> kClasses = {
        {"read-back failed", QLatin1String("readback_failed")},
        {"the device reports", QLatin1String("readback_mismatch")},
        {"line was lost", QLatin1String("line_lost")},
        {"not connected", QLatin1String("line_down")},
        {"clos", QLatin1String("line_down")},
        {"NAK", QLatin1String("nak")},
        {"corrupted", QLatin1String("corrupted")},
        {"no answer", QLatin1String("no_answer")},
        {"could not be written", QLatin1String("no_answer")},
    };
    for (const auto &[needle, name] : kClasses)
        if (reason.contains(QLatin1String(needle)))
            return name;
    return QStringLiteral("other");
}

WriteStream::Verdict WriteStream::judge(const QByteArray &code, qint64 deviceValue) const {
    const Track t = m_tracks.value(code);
    if (t.lastVerified == deviceValue)
        return Verdict::Expected;
    for (const auto &[value, reason] : t.failedSince)
        if (value == deviceValue)
            return Verdict::FromFailedWrite;
    return Verdict::Unexpected;
}

QString WriteStream::expectationText(const QByteArray &code) const {
    const Track t = m_tracks.value(code);
    QStringList failed;
    for (const auto &[value, reason] : t.failedSince)
        failed.append(QString::number(value));
    return QStringLiteral("last verified %1, failed since: [%2]")
        .arg(t.lastVerified ? QString::number(*t.lastVerified) : QStringLiteral("none"),
             failed.join(QLatin1Char(' ')));
}

QString WriteStream::failureReason(const QByteArray &code, qint64 value) const {
    const Track t = m_tracks.value(code);
    for (const auto &[v, reason] : t.failedSince)
        if (v == value)
            return reason;
    return {};
}

} // namespace tipscope::bench
