#include "mqtttopic.h"

#include <QStringList>

namespace tipscope::mqtt {

namespace {

constexpr int kMaxTopicBytes = 65535;

bool isKeptCharacter(char32_t c) {
    return (c >= U'a' && c <= U'z') || (c >= U'0' && c <= U'9') || c == U'_' || c == U'-';
}

bool hasValidLength(const QString &text) {
    return !text.isEmpty() && text.toUtf8().size() <= kMaxTopicBytes &&
           !text.contains(QChar(u'\0'));
}

} // namespace

QString sanitizeTopicLevel(const QString &name) {
    if (name.isEmpty())
        return QStringLiteral("_");
    QString level;
    for (const char32_t c : name.toLower().toUcs4())
        level += isKeptCharacter(c) ? QChar(static_cast<char16_t>(c)) : QChar(u'_');
    return level;
}

bool isValidTopicName(const QString &topic) {
    return hasValidLength(topic) && !topic.contains(u'+') && !topic.contains(u'#');
}

bool isValidTopicFilter(const QString &filter) {
    if (!hasValidLength(filter))
        return false;
    const QStringList levels = filter.split(u'/');
    for (int i = 0; i < levels.size(); ++i) {
        const QString &level = levels.at(i);
        if (level.contains(u'+') && level != QLatin1String("+"))
            return false;
        if (level.contains(u'#') && (level != QLatin1String("#") || i != levels.size() - 1))
            return false;
    }
    return true;
}

bool topicMatchesFilter(const QString &topic, const QString &filter) {
    if (!isValidTopicName(topic) || !isValidTopicFilter(filter))
        return false;
    if (topic.startsWith(u'$') && (filter.startsWith(u'+') || filter.startsWith(u'#')))
        return false;
    const QStringList topicLevels = topic.split(u'/');
    const QStringList filterLevels = filter.split(u'/');
    for (int i = 0; i < filterLevels.size(); ++i) {
        const QString &level = filterLevels.at(i);
        if (level == QLatin1String("#"))
            return true; // also matches the parent: "a/#" matches "a"
        if (i >= topicLevels.size())
            return false;
        if (level != QLatin1String("+") && level != topicLevels.at(i))
            return false;
    }
    return topicLevels.size() == filterLevels.size();
}

} // namespace tipscope::mqtt
