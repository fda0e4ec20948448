#include "planttopics.h"

#include "mqtt/mqtttopic.h"

#include <QStringList>

namespace tipscope::plant {

using mqtt::sanitizeTopicLevel;

namespace {
const QString kAgentLevel = QStringLiteral("_agent");
}

QString deviceLevel(const QString &name, std::optional<int> address, const QString &family) {
    if (!name.isEmpty())
        return sanitizeTopicLevel(name);
    const QString where = address ? QStringLiteral("%1-").arg(*address, 2, 10, QLatin1Char('0'))
                                  : QStringLiteral("--");
    return sanitizeTopicLevel(where + family);
}

QString deviceRoot(const QString &site, const QString &line, const QString &device) {
    QString lineLevel = sanitizeTopicLevel(line);
    if (lineLevel == kAgentLevel) // the agents' own level: a line of that name steps aside
        lineLevel.prepend(QLatin1Char('_'));
    return QStringList{QLatin1String(kTopicPrefix), sanitizeTopicLevel(site), lineLevel,
                       sanitizeTopicLevel(device)}
        .join(QLatin1Char('/'));
}

QString agentRoot(const QString &site, const QString &agentId) {
    return QStringList{QLatin1String(kTopicPrefix), sanitizeTopicLevel(site), kAgentLevel,
                       sanitizeTopicLevel(agentId)}
        .join(QLatin1Char('/'));
}

DevicePlace devicePlace(const QString &site, const QString &agentId, const QString &line,
                        const QString &name, std::optional<int> address, const QString &family) {
    const QString level = deviceLevel(name, address, family);
    return {line, name, deviceRoot(site, line, level),
            QStringLiteral("%1-%2-%3").arg(agentId, sanitizeTopicLevel(line), level)};
}

DevicePlace agentPlace(const QString &site, const QString &agentId) {
    return {QString(), QString(), agentRoot(site, agentId), QString()};
}

std::optional<DeviceTopic> parseDeviceTopic(const QString &topic) {
    const QStringList levels = topic.split(QLatin1Char('/'));
    // tipscope / v1 / site / line / device / leaf...
    if (levels.size() < 6 || levels.at(0) != QLatin1String("tipscope") ||
        levels.at(1) != QLatin1String("v1") || levels.at(3) == kAgentLevel)
        return std::nullopt;
    for (int i = 2; i < levels.size(); ++i)
        if (levels.at(i).isEmpty())
            return std::nullopt;
    return DeviceTopic{levels.at(2), levels.at(3), levels.at(4),
                       levels.mid(5).join(QLatin1Char('/'))};
}

} // namespace tipscope::plant
