#include "jointbench.h"

#include "benchsupport.h"
#include "jointwirebench.h"
#include "model/joints/jointdetector.h"

#include <QRandomGenerator>
#include <cmath>

namespace tipscope::bench {

using namespace tipscope::model;

namespace {
constexpr int kSetpoint = 350;
constexpr int kBandK = 5;
constexpr qint64 kMatchMs = 1000;

// A true joint: where the tip leaves and re-enters the band, as the continuous curve does.
struct TrueJoint {
    qint64 leaveMs;
    qint64 returnMs;
};

// The tip at any instant: the setpoint, a joint's dip, a heat-up or a sleep.
class Port {
public:
    enum class Phase { Joint, HeatUp, Sleep, Off };
    struct Segment {
        Phase phase;
        qint64 startMs;
        qint64 endMs;
        double dip = 0;    // K
        qint64 dropMs = 0; // to the bottom
        double tauMs = 0;  // recovery time constant
    };

    void add(const Segment &s) { m_segments.append(s); }
    [[nodiscard]] const QList<Segment> &segments() const { return m_segments; }

    // Tip temperature, power and whether the port is working at `t`.
    [[nodiscard]] std::tuple<double, double, bool> at(qint64 t) {
        while (m_next < m_segments.size() && m_segments.at(m_next).endMs <= t)
            ++m_next;
        if (m_next >= m_segments.size() || t < m_segments.at(m_next).startMs)
            return {kSetpoint, 8, true};
        const Segment &s = m_segments.at(m_next);
        const double d = double(t - s.startMs);
        switch (s.phase) {
        case Phase::Joint: {
            if (d < double(s.dropMs))
                return {kSetpoint - s.dip * d / double(s.dropMs), 90, true};
            const double below = s.dip * std::exp(-(d - double(s.dropMs)) / s.tauMs);
            return {kSetpoint - below, qMin(100.0, 8 + below * 2), true};
        }
        case Phase::HeatUp:
            return {qMin(double(kSetpoint), 25 + d * 0.15), 100, true};
        case Phase::Sleep:
            return {200, 0, false};
        case Phase::Off:
            return {25, 0, false};
        }
        return {kSetpoint, 8, true};
    }

private:
    QList<Segment> m_segments;
    qsizetype m_next = 0;
};

// The port's day: joints with settled stretches between them, heat-ups and sleeps among them.
Port makePort(int joints, QRandomGenerator &random, QList<TrueJoint> *truth) {
    Port port;
    qint64 t = 10'000;
    for (int i = 0; i < joints; ++i) {
        if (i % 40 == 39) { // switched off, then heated from cold
            port.add({Port::Phase::Off, t, t + 3000, 0, 0, 0});
            t += 3000;
            port.add({Port::Phase::HeatUp, t, t + 2400, 0, 0, 0});
            t += 2400 + 3000;
        }
        if (i % 25 == 24) {
            port.add({Port::Phase::Sleep, t, t + 5000, 0, 0, 0});
            t += 5000;
            port.add({Port::Phase::HeatUp, t, t + 1000, 0, 0, 0}); // the wake
            t += 1000 + 3000;
        }
        Port::Segment s{
            Port::Phase::Joint,          t, 0, 15 + random.bounded(86.0), 150 + random.bounded(351),
            300 + random.bounded(1700.0)};
        const double recoverMs = s.tauMs * std::log(s.dip / kBandK);
        s.endMs = t + s.dropMs + qint64(recoverMs + 5 * s.tauMs);
        port.add(s);
        truth->append({t + qint64(double(s.dropMs) * kBandK / s.dip),
                       t + s.dropMs + qint64(std::llround(recoverMs))});
        t = s.endMs + 2500 + random.bounded(3000);
    }
    return port;
}

struct Result {
    double precision = 0;
    double recall = 0;
    QList<double> errors;
};

Result measure(int joints, quint32 seed, qint64 periodMs, double noiseK) {
    QRandomGenerator random(seed);
    QList<TrueJoint> truth;
    Port port = makePort(joints, random, &truth);
    const qint64 end = port.segments().last().endMs + 5000;
    JointDetector detector({}, 1, JointLimits{kBandK, 3000, 120});
    QList<JointRecord> found;
    for (qint64 t = 0; t < end; t += qint64(double(periodMs) * (0.7 + random.bounded(0.6)))) {
        const auto [tip, power, working] = port.at(t);
        const int noisy = int(std::lround(tip + (random.bounded(2.0) - 1.0) * noiseK));
        if (const auto j = detector.add(
                PortReading{t, noisy, kSetpoint, power, working, QStringLiteral("C245")}))
            found.append(*j);
    }
    Result r;
    int matched = 0;
    qsizetype next = 0;
    QList<bool> used(truth.size(), false);
    for (const JointRecord &j : std::as_const(found)) {
        while (next < truth.size() && truth.at(next).leaveMs < j.startMs - kMatchMs)
            ++next;
        for (qsizetype k = next; k < truth.size() && truth.at(k).leaveMs <= j.startMs + kMatchMs;
             ++k) {
            if (used.at(k))
                continue;
            used[k] = true;
            ++matched;
            if (j.recoveryMs)
                r.errors.append(
                    std::abs(double(*j.recoveryMs - (truth.at(k).returnMs - truth.at(k).leaveMs))));
            break;
        }
    }
    r.precision = found.isEmpty() ? 0 : double(matched) / double(found.size());
    r.recall = truth.isEmpty() ? 0 : double(matched) / double(truth.size());
    return r;
}
} // namespace

int runJointBench(const QStringList &args) {
    if (args.contains(QStringLiteral("--wire")))
        return runJointWireBench(args);
    const std::optional<qint64> jointsOption = wholeOption(args, "--joints", 500, 1, 1'000'000);
    const std::optional<qint64> seedOption = wholeOption(args, "--seed", 1, 0, UINT32_MAX);
    const std::optional<double> noiseOption = numberOption(args, "--noise", 0.5, 0, 50);
    if (!jointsOption || !seedOption || !noiseOption)
        return 2;
    const int joints = int(*jointsOption);
    const auto seed = quint32(*seedOption);
    const double noiseK = *noiseOption;
    printFigure(QStringLiteral("joints.count"), joints, QStringLiteral("joints"), 0);
    printFigure(QStringLiteral("joints.noise"), noiseK, QStringLiteral("K"), 1);
    for (const qint64 period : {100, 300}) {
        const Result r = measure(joints, seed, period, noiseK);
        const QString name = QStringLiteral("joints.%1ms.").arg(period);
        printFigure(name + QStringLiteral("precision"), r.precision, QString(), 4);
        printFigure(name + QStringLiteral("recall"), r.recall, QString(), 4);
        printFigure(name + QStringLiteral("recovery_error_p50_ms"), quantile(r.errors, 0.5),
                    QStringLiteral("ms"), 0);
        printFigure(name + QStringLiteral("recovery_error_p95_ms"), quantile(r.errors, 0.95),
                    QStringLiteral("ms"), 0);
    }
    return 0;
}

} // namespace tipscope::bench
