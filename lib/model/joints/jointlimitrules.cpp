#include "model/joints/jointlimitrules.h"

#include "base/elide.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QLocale>
#include <cmath>

namespace tipscope::model {

namespace {
struct JointLimitRulesTr {
    Q_DECLARE_TR_FUNCTIONS(JointLimitRules)
};

using base::failure;
using base::Outcome;

const QString kPort = QStringLiteral("port");
const QString kTool = QStringLiteral("tool");
const QString kRecovery = QStringLiteral("max_recovery_s");
const QString kDip = QStringLiteral("max_dip_k");
const QString kWear = QStringLiteral("wear_share");

constexpr double kMaxRecoveryS = 600;
constexpr int kMaxDipK = 500;

// Specificity of a rule: 0 matches nothing more than the defaults would.
int rank(const JointLimitRule &rule) {
    return (rule.tool.isEmpty() ? 0 : 2) + (rule.port ? 1 : 0);
}

bool matches(const JointLimitRule &rule, int port, const QString &tool) {
    return (!rule.port || *rule.port == port) &&
           (rule.tool.isEmpty() || rule.tool.compare(tool, Qt::CaseInsensitive) == 0);
}

void apply(const JointLimitRule &rule, JointLimits &limits) {
    if (rule.maxRecoveryMs)
        limits.maxRecoveryMs = *rule.maxRecoveryMs;
    if (rule.maxDipK)
        limits.maxDipK = *rule.maxDipK;
    if (rule.wearShare)
        limits.wearShare = *rule.wearShare;
}

Outcome<qint64> recoveryMsOf(double seconds) {
    if (!std::isfinite(seconds) || seconds <= 0 || seconds > kMaxRecoveryS)
        return failure(
            JointLimitRulesTr::tr("the longest recovery must be more than 0 s and at most %1 s")
                .arg(kMaxRecoveryS));
    return qRound64(seconds * 1000);
}

Outcome<int> dipOf(double k) {
    if (!std::isfinite(k) || k <= 0 || k > kMaxDipK || k != std::floor(k))
        return failure(
            JointLimitRulesTr::tr("the deepest dip must be a whole number of kelvin from 1 to %1")
                .arg(kMaxDipK));
    return int(k);
}

Outcome<double> wearOf(double share) {
    if (!std::isfinite(share) || share <= 0 || share > 10)
        return failure(
            JointLimitRulesTr::tr("the tip wear share must be more than 0 and at most 10"));
    return share;
}

Outcome<int> portOf(double port) {
    if (!std::isfinite(port) || port < 1 || port > 4 || port != std::floor(port))
        return failure(JointLimitRulesTr::tr("a port is a number from 1 to 4"));
    return int(port);
}

// Sets one limit of `rule`, or says why the value is refused.
Outcome<void> setLimit(JointLimitRule &rule, const QString &name, double value) {
    if (name == kRecovery) {
        const auto ms = recoveryMsOf(value);
        if (!ms)
            return failure(ms.error());
        rule.maxRecoveryMs = ms.value();
    } else if (name == kDip) {
        const auto k = dipOf(value);
        if (!k)
            return failure(k.error());
        rule.maxDipK = k.value();
    } else if (name == kWear) {
        const auto share = wearOf(value);
        if (!share)
            return failure(share.error());
        rule.wearShare = share.value();
    }
    return {};
}

Outcome<JointLimitRule> ruleFromJson(const QJsonObject &o) {
    JointLimitRule rule;
    if (o.contains(kPort)) {
        const auto port = portOf(o.value(kPort).toDouble(-1));
        if (!port)
            return failure(port.error());
        rule.port = port.value();
    }
    rule.tool = o.value(kTool).toString().trimmed();
    for (const QString &name : {kRecovery, kDip, kWear}) {
        if (!o.contains(name))
            continue;
        if (!o.value(name).isDouble())
            return failure(JointLimitRulesTr::tr("%1 must be a number").arg(name));
        if (const auto set = setLimit(rule, name, o.value(name).toDouble()); !set)
            return failure(set.error());
    }
    return rule;
}

QJsonObject limitsJson(const JointLimitRule &rule) {
    QJsonObject o;
    if (rule.port)
        o.insert(kPort, *rule.port);
    if (!rule.tool.isEmpty())
        o.insert(kTool, rule.tool);
    if (rule.maxRecoveryMs)
        o.insert(kRecovery, double(*rule.maxRecoveryMs) / 1000);
    if (rule.maxDipK)
        o.insert(kDip, *rule.maxDipK);
    if (rule.wearShare)
        o.insert(kWear, *rule.wearShare);
    return o;
}

JointLimitRule asRule(const JointLimits &limits) {
    return {std::nullopt, {}, limits.maxRecoveryMs, limits.maxDipK, limits.wearShare};
}
} // namespace

void JointLimitRules::add(const JointLimitRule &rule) {
    for (JointLimitRule &r : m_rules) {
        if (r.port == rule.port && r.tool.compare(rule.tool, Qt::CaseInsensitive) == 0) {
            r = rule;
            return;
        }
    }
    m_rules.append(rule);
}

JointLimits JointLimitRules::limitsFor(int port, const QString &tool) const {
    JointLimits limits = m_defaults;
    // Least specific first, so the most specific rule is applied last and wins.
    for (int r = 0; r <= 3; ++r)
        for (const JointLimitRule &rule : m_rules)
            if (rank(rule) == r && matches(rule, port, tool))
                apply(rule, limits);
    return limits;
}

QJsonObject JointLimitRules::toJson() const {
    QJsonArray rules;
    for (const JointLimitRule &rule : m_rules)
        rules.append(limitsJson(rule));
    return {{QStringLiteral("default"), limitsJson(asRule(m_defaults))},
            {QStringLiteral("rules"), rules}};
}

Outcome<JointLimitRules> JointLimitRules::fromJson(const QJsonObject &json) {
    JointLimitRules out;
    const auto defaults = ruleFromJson(json.value(QStringLiteral("default")).toObject());
    if (!defaults)
        return failure(JointLimitRulesTr::tr("joint limits: %1").arg(defaults.error()));
    apply(defaults.value(), out.m_defaults);
    const QJsonArray rules = json.value(QStringLiteral("rules")).toArray();
    for (qsizetype i = 0; i < rules.size(); ++i) {
        const auto rule = ruleFromJson(rules.at(i).toObject());
        if (!rule)
            return failure(
                JointLimitRulesTr::tr("joint limit rule %1: %2").arg(i + 1).arg(rule.error()));
        out.add(rule.value());
    }
    return out;
}

Outcome<JointLimitRule> JointLimitRules::parseRule(const QString &text) {
    static const QMap<QString, QString> kWords = {{QStringLiteral("recovery"), kRecovery},
                                                  {QStringLiteral("dip"), kDip},
                                                  {QStringLiteral("wear"), kWear}};
    JointLimitRule rule;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString name = part.section(QLatin1Char('='), 0, 0).trimmed().toLower();
        const QString value = part.section(QLatin1Char('='), 1).trimmed();
        bool isNumber = false;
        const double number = QLocale::c().toDouble(value, &isNumber);
        if (name == kTool && !value.isEmpty()) {
            rule.tool = value;
        } else if (name == kPort && isNumber) {
            const auto port = portOf(number);
            if (!port)
                return failure(port.error());
            rule.port = port.value();
        } else if (kWords.contains(name) && isNumber) {
            if (const auto set = setLimit(rule, kWords.value(name), number); !set)
                return failure(set.error());
        } else {
            return failure(JointLimitRulesTr::tr(
                               "“%1” is not a limit: write port=N, tool=NAME, recovery=SECONDS, "
                               "dip=KELVIN or wear=SHARE, joined by commas")
                               .arg(base::elided(part.trimmed())));
        }
    }
    if (!rule.maxRecoveryMs && !rule.maxDipK && !rule.wearShare)
        return failure(
            JointLimitRulesTr::tr("“%1” sets no limit: give recovery=SECONDS, dip=KELVIN or "
                                  "wear=SHARE")
                .arg(base::elided(text)));
    return rule;
}

QString JointLimitRules::ruleText(const JointLimitRule &rule) {
    QStringList parts;
    if (rule.port)
        parts << QStringLiteral("port=%1").arg(*rule.port);
    if (!rule.tool.isEmpty())
        parts << QStringLiteral("tool=%1").arg(rule.tool);
    if (rule.maxRecoveryMs)
        parts << QStringLiteral("recovery=%1").arg(double(*rule.maxRecoveryMs) / 1000);
    if (rule.maxDipK)
        parts << QStringLiteral("dip=%1").arg(*rule.maxDipK);
    if (rule.wearShare)
        parts << QStringLiteral("wear=%1").arg(*rule.wearShare);
    return parts.join(QLatin1Char(','));
}

bool operator==(const JointLimitRules &a, const JointLimitRules &b) {
    return a.m_defaults == b.m_defaults && a.m_rules == b.m_rules;
}

} // namespace tipscope::model
