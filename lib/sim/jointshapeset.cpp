#include "jointshapeset.h"

#include <cmath>

namespace tipscope::sim {

namespace {

int uniform(QRandomGenerator &random, int low, int high) {
    return low + int(random.bounded(qMax(0, high - low) + 1));
}

// A triangular distribution from low to high, most likely at mode.
double triangular(QRandomGenerator &random, double low, double mode, double high) {
    const double u = random.generateDouble();
    const double split = (mode - low) / (high - low);
    return u < split ? low + std::sqrt(u * (high - low) * (mode - low))
                     : high - std::sqrt((1 - u) * (high - low) * (high - mode));
}

JointShapeSet demoSet() {
    JointShapeSet s;
    s.name = QStringLiteral("demo");
    return s;
}

JointShapeSet variedSet() {
    JointShapeSet s;
    s.name = QStringLiteral("varied");
    s.minDepthK = 25;
    s.maxDepthK = 90;
    s.minDropMs = 50;
    s.maxDropMs = 400;
    s.typicalDropMs = 150;
    s.minRecoveryMs = 600;
    s.maxRecoveryMs = 3500;
    s.linearShare = 0.5;
    s.maxOvershootK = 3;
    s.noiseK = 2;
    s.noiseDuringJoints = true;
    s.restMs = 1200;
    return s;
}

JointShapeSet slowSet() {
    JointShapeSet s;
    s.name = QStringLiteral("slow");
    s.minDepthK = 10;
    s.maxDepthK = 25;
    s.minDropMs = 200;
    s.maxDropMs = 400;
    s.minRecoveryMs = 3000;
    s.maxRecoveryMs = 6000;
    s.linearShare = 0.7;
    s.noiseK = 1;
    s.noiseDuringJoints = true;
    s.restMs = 2000;
    return s;
}

const QList<JointShapeSet> &allSets() {
    static const QList<JointShapeSet> sets{demoSet(), variedSet(), slowSet()};
    return sets;
}

} // namespace

JointSpec JointShapeSet::draw(QRandomGenerator &random) const {
    JointSpec spec;
    spec.depthK = uniform(random, minDepthK, maxDepthK);
    spec.recoveryMs = uniform(random, minRecoveryMs, maxRecoveryMs);
    if (maxDropMs > 0)
        spec.dropMs = typicalDropMs > minDropMs && typicalDropMs < maxDropMs
                          ? triangular(random, minDropMs, typicalDropMs, maxDropMs)
                          : double(uniform(random, minDropMs, maxDropMs));
    if (linearShare > 0 && random.generateDouble() < linearShare)
        spec.form = RecoveryForm::Linear;
    if (maxOvershootK > 0)
        spec.overshootK = maxOvershootK * random.generateDouble();
    return spec;
}

std::optional<JointShapeSet> JointShapeSet::named(const QString &name) {
    for (const JointShapeSet &s : allSets())
        if (s.name == name)
            return s;
    return std::nullopt;
}

QStringList JointShapeSet::names() {
    QStringList names;
    for (const JointShapeSet &s : allSets())
        names.append(s.name);
    return names;
}

} // namespace tipscope::sim
