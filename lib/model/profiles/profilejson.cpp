#include "profilejson.h"

#include <QCoreApplication>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <vector>

namespace tipscope::model::profilejson {

namespace {

struct ProfileJsonTr {
    Q_DECLARE_TR_FUNCTIONS(Profile)
};

// One open object or array while the text is walked.
struct Level {
    bool isObject = false;
    QString path;    // "" at the top, "values", "values.x" ...
    QString lastKey; // the key whose value comes next
    bool expectKey = false;
    QHash<QString, int> seen;
};

// A JSON string token, quotes included, as its text. Escapes are left to Qt's own parser.
QString decodeString(const QByteArray &token) {
    if (!token.contains('\\'))
        return QString::fromUtf8(token.mid(1, token.size() - 2));
    const QJsonDocument doc = QJsonDocument::fromJson('[' + token + ']');
    return doc.array().at(0).toString();
}

qsizetype stringEnd(const QByteArray &json, qsizetype open) {
    qsizetype i = open + 1;
    while (i < json.size() && json.at(i) != '"')
        i += json.at(i) == '\\' ? 2 : 1;
    return qMin(i, json.size() - 1);
}

class KeyScan {
public:
    QStringList run(const QByteArray &json) {
        for (qsizetype i = 0; i < json.size(); ++i) {
            const char c = json.at(i);
            if (c == '"') {
                const qsizetype end = stringEnd(json, i);
                string(json.mid(i, end - i + 1));
                i = end;
            } else if (c == '{' || c == '[') {
                open(c == '{');
            } else if ((c == '}' || c == ']') && !m_stack.empty()) {
                m_stack.pop_back();
            } else if (c == ',' && !m_stack.empty() && m_stack.back().isObject) {
                m_stack.back().expectKey = true;
            }
        }
        return m_duplicates;
    }

private:
    void open(bool isObject) {
        Level next;
        next.isObject = isObject;
        next.expectKey = isObject;
        if (!m_stack.empty()) {
            const Level &parent = m_stack.back();
            const QString name = parent.isObject ? parent.lastKey : QString();
            next.path = parent.path.isEmpty() ? name : parent.path + QLatin1Char('.') + name;
        }
        m_stack.push_back(next);
    }

    void string(const QByteArray &token) {
        if (m_stack.empty() || !m_stack.back().isObject || !m_stack.back().expectKey)
            return;
        Level &level = m_stack.back();
        level.expectKey = false;
        level.lastKey = decodeString(token);
        // The codes of "values" are applied upper-cased: "st1" is ST1.
        const bool codes = m_stack.size() == 2 && level.path == QLatin1String("values");
        const QString key = codes ? level.lastKey.toUpper() : level.lastKey;
        if (++level.seen[key] != 2)
            return;
        const bool nested = !level.path.isEmpty() && !codes;
        m_duplicates.append(nested ? level.path + QLatin1Char('.') + key : key);
    }

    std::vector<Level> m_stack;
    QStringList m_duplicates;
};

bool isJsonSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// The index just past the value that starts at `i` in valid JSON.
qsizetype valueEnd(const QByteArray &json, qsizetype i) {
    const char first = json.at(i);
    if (first == '"')
        return stringEnd(json, i) + 1;
    if (first != '{' && first != '[') { // a number, true, false or null
        while (i < json.size() && !isJsonSpace(json.at(i)) &&
               !QByteArray(",}]").contains(json.at(i)))
            ++i;
        return i;
    }
    int depth = 0;
    for (; i < json.size(); ++i) {
        const char c = json.at(i);
        if (c == '"')
            i = stringEnd(json, i);
        else if (c == '{' || c == '[')
            ++depth;
        else if ((c == '}' || c == ']') && --depth == 0)
            return i + 1;
    }
    return i;
}

} // namespace

QString controlCharacterProblem(const QByteArray &json) {
    for (qsizetype i = 0; i < json.size(); ++i) {
        const auto b = quint8(json.at(i));
        if (b >= 0x20 || b == '\t' || b == '\n' || b == '\r')
            continue;
        if (b == 0)
            return ProfileJsonTr::tr("a NUL byte at byte %1").arg(i + 1);
        return ProfileJsonTr::tr("control character 0x%1 at byte %2")
            .arg(b, 2, 16, QLatin1Char('0'))
            .arg(i + 1);
    }
    return {};
}

QStringList duplicateKeys(const QByteArray &json) {
    return KeyScan().run(json);
}

QList<Member> topLevelMembers(const QByteArray &json) {
    QList<Member> members;
    qsizetype i = json.indexOf('{');
    if (i < 0)
        return members;
    for (++i; i < json.size(); ++i) {
        if (json.at(i) != '"')
            continue; // spaces and commas between members
        const qsizetype keyEnd = stringEnd(json, i);
        const QString key = decodeString(json.mid(i, keyEnd - i + 1));
        i = json.indexOf(':', keyEnd) + 1;
        while (i > 0 && i < json.size() && isJsonSpace(json.at(i)))
            ++i;
        if (i <= 0 || i >= json.size())
            break;
        const qsizetype end = valueEnd(json, i);
        members.append({key, json.mid(i, end - i)});
        i = end - 1;
    }
    return members;
}

} // namespace tipscope::model::profilejson
