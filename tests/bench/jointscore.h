// How the joints a front end found compare with the ones the simulator made, for
// `tipscope-bench joints --wire`: matched one to one by port and start (within 1 s), over the
// joints that began once the front end was reading and ended before it stopped.
#pragma once

#include "model/joints/jointrecord.h"
#include "sim/jointshape.h"

#include <QList>
#include <QString>

namespace tipscope::bench {

struct JointFigure {
    QString name;
    double value;
    QString unit;
    int decimals;
};

// What a simulator made: each joint as it began, completed by its end (reads, read depth).
class JointTruth {
public:
    void made(const sim::SimJoint &joint) { m_joints.append(joint); }
    void ended(const sim::SimJoint &joint);
    // Reads the lines tipscope-sim logs on standard error ("joint ..." and "joint-end ...").
    void parseLog(const QString &text);
    [[nodiscard]] const QList<sim::SimJoint> &joints() const { return m_joints; }

private:
    QList<sim::SimJoint> m_joints;
};

// precision, recall, the errors of recovery (of those given as measured), start and dip (p50, p95,
// max), the recovery's bias, the dip error of an oracle that knew the true tip at the same sample
// instants, how many recoveries were only bounded and the share of those bounds that hold the
// true recovery. Joints outside [fromMs, untilMs) are left out; each one missed
// is named on standard error with `label`.
[[nodiscard]] QList<JointFigure> scoreJoints(const JointTruth &truth,
                                             const QList<model::JointRecord> &found, qint64 fromMs,
                                             qint64 untilMs, const QString &label);

} // namespace tipscope::bench
