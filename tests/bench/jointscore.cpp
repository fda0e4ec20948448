#include "jointscore.h"

#include "benchsupport.h"

#include <QRegularExpression>

namespace tipscope::bench {

namespace {
constexpr qint64 kMatchMs = 1000;
} // namespace

void JointTruth::ended(const sim::SimJoint &joint) {
    for (sim::SimJoint &j : m_joints)
        if (j.port == joint.port && j.startMs == joint.startMs) {
            j.reads = joint.reads;
            j.readDepthK = joint.readDepthK;
            return;
        }
}

void JointTruth::parseLog(const QString &text) {
    static const QRegularExpression made(QStringLiteral(
        "^tipscope-sim: joint port=(\\d+) start_ms=(\\d+) depth_k=(\\d+) recovery_ms=(\\d+) "
        "drop_ms=(\\d+) form=(\\w+) overshoot_k=([\\d.]+)$"));
    static const QRegularExpression ended(
        QStringLiteral("^tipscope-sim: joint-end port=(\\d+) start_ms=(\\d+) reads=(\\d+) "
                       "read_depth_k=([\\d.]+)$"));
    const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (const QString &line : lines) {
        if (const auto m = made.match(line); m.hasMatch()) {
            sim::SimJoint j;
            j.port = m.captured(1).toInt();
            j.startMs = m.captured(2).toLongLong();
            j.depthK = m.captured(3).toInt();
            j.recoveryMs = m.captured(4).toLongLong();
            j.dropMs = m.captured(5).toDouble();
            j.form = m.captured(6) == QLatin1String("linear") ? sim::RecoveryForm::Linear
                                                              : sim::RecoveryForm::Exponential;
            j.overshootK = m.captured(7).toDouble();
            m_joints.append(j);
        } else if (const auto e = ended.match(line); e.hasMatch()) {
            sim::SimJoint j;
            j.port = e.captured(1).toInt();
            j.startMs = e.captured(2).toLongLong();
            j.reads = e.captured(3).toInt();
            j.readDepthK = e.captured(4).toDouble();
            this->ended(j);
        }
    }
}

QList<JointFigure> scoreJoints(const JointTruth &truth, const QList<model::JointRecord> &found,
                               qint64 fromMs, qint64 untilMs, const QString &label) {
    // A joint counts when it began once the front end read the station and was over (with a
    // second to spare for the front end to end it) before the run ended. A joint found is
    // matched against every joint made, counted or not: one that matches a joint left out is
    // left out too, and one that matches none is a false one if it began within the run.
    const qint64 cutoff = untilMs - kMatchMs;
    constexpr qsizetype kWorstShown = 5;
    const QList<sim::SimJoint> &all = truth.joints();
    const auto counted = [&](const sim::SimJoint &t) {
        return t.startMs >= fromMs && t.startMs + t.recoveryMs < cutoff;
    };
    QList<bool> used(all.size(), false);
    QList<double> recoveryErrors, startErrors, dipErrors, oracleDipErrors;
    QList<double> startUncertainties, dipUncertainties; // what the records say, to judge them by
    double signedSum = 0;                               // measured minus true: a bias shows here
    int matched = 0, bounded = 0, holding = 0, seen = 0;
    // How often the stated uncertainty of the start and the dip holds the truth: a figure on a
    // customer's record is only as good as the interval it is given with.
    int startsHeld = 0, dipsHeld = 0;
    double startSignedSum = 0, dipSignedSum = 0; // measured minus true
    QList<model::JointRecord> unmade;            // found, but matching no joint made
    // The recoveries measured furthest off, for whoever looks into the p95.
    struct Miss {
        double errorMs;
        sim::SimJoint made;
        model::JointRecord found;
    };
    QList<Miss> worst;
    for (const model::JointRecord &j : found) {
        qsizetype match = -1;
        for (qsizetype k = 0; k < all.size() && match < 0; ++k)
            if (!used.at(k) && all.at(k).port == j.port &&
                qAbs(all.at(k).startMs - j.startMs) <= kMatchMs)
                match = k;
        if (match < 0) {
            if (j.startMs >= fromMs && j.startMs + j.recoveryMs.value_or(j.durationMs) < cutoff) {
                ++seen;
                unmade.append(j);
            }
            continue;
        }
        used[match] = true;
        const sim::SimJoint &t = all.at(match);
        if (!counted(t))
            continue;
        ++seen;
        ++matched;
        startErrors.append(double(qAbs(j.startMs - t.startMs)));
        dipErrors.append(qAbs(j.dipDepth - t.depthK));
        startsHeld += qAbs(j.startMs - t.startMs) <= j.startUncertaintyMs;
        startSignedSum += double(j.startMs - t.startMs);
        startUncertainties.append(double(j.startUncertaintyMs));
        dipUncertainties.append(j.dipUncertaintyK);
        dipSignedSum += j.dipDepth - t.depthK;
        dipsHeld += qAbs(j.dipDepth - t.depthK) <= j.dipUncertaintyK;
        if (t.reads > 0)
            oracleDipErrors.append(qMax(0.0, t.depthK - t.readDepthK));
        // A bounded recovery is judged by whether its interval holds the truth; the errors are
        // those of the recoveries given as measured.
        if (j.recoveryMs && j.recoveryBounded) {
            ++bounded;
            holding += qAbs(*j.recoveryMs - t.recoveryMs) <= j.recoveryUncertaintyMs;
        } else if (j.recoveryMs) {
            recoveryErrors.append(double(qAbs(*j.recoveryMs - t.recoveryMs)));
            signedSum += double(*j.recoveryMs - t.recoveryMs);
            worst.append({double(*j.recoveryMs - t.recoveryMs), t, j});
        }
    }
    std::sort(worst.begin(), worst.end(),
              [](const Miss &a, const Miss &b) { return qAbs(a.errorMs) > qAbs(b.errorMs); });
    for (const Miss &m : worst.mid(0, kWorstShown))
        printNote(QStringLiteral("%1 recovery off by %2 ms (±%3 said): port %4, %5 K, recovery "
                                 "%6 ms, drop %7 ms, %8, overshoot %9 K")
                      .arg(label)
                      .arg(m.errorMs)
                      .arg(m.found.recoveryUncertaintyMs)
                      .arg(m.made.port)
                      .arg(m.made.depthK)
                      .arg(m.made.recoveryMs)
                      .arg(qRound(m.made.dropMs))
                      .arg(sim::recoveryFormName(m.made.form))
                      .arg(m.made.overshootK, 0, 'f', 1));
    int made = 0;
    for (const sim::SimJoint &t : all)
        made += counted(t);
    // What was missed, and what was found that nobody made, on standard error, for whoever
    // looks into the recall and the precision.
    for (qsizetype k = 0; k < all.size(); ++k) {
        const sim::SimJoint &t = all.at(k);
        if (used.at(k) || !counted(t))
            continue;
        QString near;
        for (const model::JointRecord &j : found)
            if (j.port == t.port && qAbs(j.startMs - t.startMs) < 10'000)
                near += QStringLiteral(" [found %1 ms %2]")
                            .arg(j.startMs - t.startMs)
                            .arg(model::jointVerdictName(j.verdict));
        printNote(QStringLiteral("%1 missed: port %2, %3 ms into the run, %4 K, recovery %5 ms, "
                                 "drop %6 ms, %7;%8")
                      .arg(label)
                      .arg(t.port)
                      .arg(t.startMs - fromMs)
                      .arg(t.depthK)
                      .arg(t.recoveryMs)
                      .arg(qRound(t.dropMs))
                      .arg(sim::recoveryFormName(t.form), near));
    }
    for (const model::JointRecord &j : std::as_const(unmade)) {
        QString near;
        for (const sim::SimJoint &t : all)
            if (t.port == j.port && qAbs(j.startMs - t.startMs) < 10'000)
                near += QStringLiteral(" [made %1 ms earlier, %2 K, recovery %3 ms]")
                            .arg(j.startMs - t.startMs)
                            .arg(t.depthK)
                            .arg(t.recoveryMs);
        printNote(QStringLiteral("%1 found what was not made: port %2, %3 ms into the run, dip "
                                 "%4 K, recovery %5 ms, %6;%7")
                      .arg(label)
                      .arg(j.port)
                      .arg(j.startMs - fromMs)
                      .arg(j.dipDepth, 0, 'f', 1)
                      .arg(j.recoveryMs.value_or(-1))
                      .arg(model::jointVerdictName(j.verdict), near));
    }
    const QString ms = QStringLiteral("ms");
    const QString k = QStringLiteral("K");
    return {
        {QStringLiteral("true"), double(made), QStringLiteral("joints"), 0},
        {QStringLiteral("found"), double(seen), QStringLiteral("joints"), 0},
        {QStringLiteral("precision"), seen == 0 ? 0 : double(matched) / double(seen), QString(), 3},
        {QStringLiteral("recall"), made == 0 ? 0 : double(matched) / double(made), QString(), 3},
        {QStringLiteral("recovery_error_p50_ms"), quantile(recoveryErrors, 0.5), ms, 0},
        {QStringLiteral("recovery_error_p95_ms"), quantile(recoveryErrors, 0.95), ms, 0},
        {QStringLiteral("recovery_error_max_ms"), quantile(recoveryErrors, 1.0), ms, 0},
        {QStringLiteral("recovery_bias_ms"),
         recoveryErrors.isEmpty() ? 0 : signedSum / double(recoveryErrors.size()), ms, 0},
        {QStringLiteral("recovery_bounded"), double(bounded), QStringLiteral("joints"), 0},
        {QStringLiteral("recovery_bounds_holding"),
         bounded == 0 ? 1.0 : double(holding) / double(bounded), QString(), 3},
        {QStringLiteral("start_error_p95_ms"), quantile(startErrors, 0.95), ms, 0},
        {QStringLiteral("start_uncertainty_p50_ms"), quantile(startUncertainties, 0.5), ms, 0},
        {QStringLiteral("start_bias_ms"), matched == 0 ? 0 : startSignedSum / matched, ms, 0},
        {QStringLiteral("start_bounds_holding"), matched == 0 ? 1.0 : double(startsHeld) / matched,
         QString(), 3},
        {QStringLiteral("dip_error_p95_k"), quantile(dipErrors, 0.95), k, 1},
        {QStringLiteral("dip_uncertainty_p50_k"), quantile(dipUncertainties, 0.5), k, 1},
        {QStringLiteral("dip_bias_k"), matched == 0 ? 0 : dipSignedSum / matched, k, 2},
        {QStringLiteral("dip_bounds_holding"), matched == 0 ? 1.0 : double(dipsHeld) / matched,
         QString(), 3},
        {QStringLiteral("dip_error_oracle_p95_k"), quantile(oracleDipErrors, 0.95), k, 1},
    };
}

} // namespace tipscope::bench
