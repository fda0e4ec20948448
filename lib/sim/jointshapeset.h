// JointShapeSet: a distribution of joints (depth, drop, recovery, form of the recovery,
// overshoot, the readings' noise, the rest between two joints) from which the random joints of a
// simulated station are drawn, so that tests and `tipscope-bench joints` measure the detector on
// stations whose joints look nothing like the demo's. Each port draws its own joints.
//
// The sets, by name (tipscope-sim --joint-shapes):
//   demo    what the simulator always made: 15-100 K, recoveries 0.4-3 s, exponential, a drop of
//           a quarter of the recovery, a ±0.6 K wobble between joints only, 3 s of rest.
//   varied  a fast station: 25-90 K within 50-400 ms (most near 150), back within 0.6-3.5 s,
//           exponential or straight, up to 3 K of overshoot, ±2 K of wobble throughout, joints
//           1.2 s apart at the least.
//   slow    slow shallow joints: 10-25 K over 200-400 ms, recoveries of 3-6 s, mostly straight,
//           ±1 K of wobble throughout.
#pragma once

#include "jointshape.h"

#include <QRandomGenerator>
#include <QString>
#include <QStringList>
#include <optional>

namespace tipscope::sim {

struct JointShapeSet {
    QString name;
    int minDepthK = 15;
    int maxDepthK = 100;
    int minDropMs = 0; // 0 and 0: a quarter of the recovery
    int maxDropMs = 0;
    int typicalDropMs = 0; // the drops cluster here (a triangular distribution); 0: uniform
    int minRecoveryMs = 400;
    int maxRecoveryMs = 3000;
    double linearShare = 0; // of the recoveries, straight rather than exponential
    double maxOvershootK = 0;
    double noiseK = kDemoWobbleK;
    bool noiseDuringJoints = false;
    int restMs = 3000; // settled at the target before the next joint

    [[nodiscard]] JointSpec draw(QRandomGenerator &random) const;

    [[nodiscard]] static std::optional<JointShapeSet> named(const QString &name);
    [[nodiscard]] static QStringList names();
};

} // namespace tipscope::sim
