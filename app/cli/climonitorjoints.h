// MonitorJoints: the joints of `tipscope-cli monitor`. Each port's readings go through the joint
// detector the GUI uses, judged by the rules for the port and its tool; each joint is printed as
// a line of its own and kept in the journal, stamped with the work context the context file
// holds (followed while the monitor runs). A journal that cannot be written is said once on
// standard error, and monitoring goes on.
#pragma once

#include "clisession.h"

#include "journal/journal.h"
#include "journal/workcontextfile.h"
#include "model/joints/jointdetector.h"
#include "model/joints/jointlimitrules.h"

#include <memory>
#include <vector>

namespace tipscope::cli {

class MonitorJoints {
public:
    MonitorJoints(CliSession &s, const link::DeviceInfo &device, int ports,
                  model::JointLimitRules rules);

    void add(int port, const model::PortReading &reading);
    // The port's readings stopped (no answer, line down): no joint is measured across it.
    void gap(int port, qint64 timeMs);
    // Ends joints in progress and waits for the journal; false when a joint could not be kept.
    bool finish();

private:
    void report(const std::optional<model::JointRecord> &joint);

    CliSession &m_session;
    model::JointLimitRules m_rules;
    std::vector<model::JointDetector> m_detectors;
    std::vector<qint64> m_lastMs;
    journal::Journal m_journal;
    std::unique_ptr<journal::WorkContextFollower> m_context; // none: the workspace's context
};

// "2026-12-02T10:41:03.120  joint P1 C245 350 °C lowest 318 °C dip 32 K recovery 1.84 s ok"
[[nodiscard]] QString monitorJointLine(const model::JointRecord &joint);

} // namespace tipscope::cli
