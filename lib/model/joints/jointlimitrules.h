// JointLimitRules: which limits judge a joint, per port and per tool.
//
// A line's joints are judged against the defaults unless a rule names their port, their tool or
// both; the most specific rule wins (port and tool, then tool, then port), and a later rule of
// the same kind replaces an earlier one. A tool is named as the family's tool table names it
// ("C245"), compared without regard to case. The same rules come from the preferences file, the
// command line (parseRule(): "port=1,tool=C245,recovery=3.5,dip=60") and, per line, a
// workspace, so they are kept as JSON:
//     {"default": {"max_recovery_s": 5, "max_dip_k": 80},
//      "rules": [{"port": 1, "tool": "C245", "max_recovery_s": 3.5, "max_dip_k": 60}]}
// A limit a rule leaves out is the default's.
#pragma once

#include "model/joints/jointdetector.h"

#include "base/outcome.h"

#include <QJsonObject>
#include <QList>

namespace tipscope::model {

struct JointLimitRule {
    std::optional<int> port; // any port when empty
    QString tool;            // any tool when empty
    std::optional<qint64> maxRecoveryMs;
    std::optional<int> maxDipK;
    std::optional<double> wearShare;

    friend bool operator==(const JointLimitRule &a, const JointLimitRule &b) {
        return a.port == b.port && a.tool == b.tool && a.maxRecoveryMs == b.maxRecoveryMs &&
               a.maxDipK == b.maxDipK && a.wearShare == b.wearShare;
    }
};

class JointLimitRules {
public:
    JointLimitRules() = default;
    explicit JointLimitRules(JointLimits defaults)
        : m_defaults(defaults) {}

    [[nodiscard]] const JointLimits &defaults() const { return m_defaults; }
    void setDefaults(const JointLimits &limits) { m_defaults = limits; }
    [[nodiscard]] const QList<JointLimitRule> &rules() const { return m_rules; }
    // Replaces the rule for the same port and tool, if there is one.
    void add(const JointLimitRule &rule);
    [[nodiscard]] JointLimits limitsFor(int port, const QString &tool) const;

    [[nodiscard]] QJsonObject toJson() const;
    [[nodiscard]] static base::Outcome<JointLimitRules> fromJson(const QJsonObject &json);
    // "port=1,tool=C245,recovery=3.5,dip=60,wear=0.3" (recovery in seconds; any part may be left
    // out, but one limit must be given).
    [[nodiscard]] static base::Outcome<JointLimitRule> parseRule(const QString &text);
    // The rule in parseRule()'s words, for listings.
    [[nodiscard]] static QString ruleText(const JointLimitRule &rule);

    friend bool operator==(const JointLimitRules &a, const JointLimitRules &b);

private:
    JointLimits m_defaults;
    QList<JointLimitRule> m_rules;
};

} // namespace tipscope::model
