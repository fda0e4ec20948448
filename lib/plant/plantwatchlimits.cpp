#include "plantwatchlimits.h"

#include "base/elide.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace tipscope::plant {

namespace {

using L = PlantWatchLimits;

// Empty, or the first bound `value` breaks. `items` is the bound of a list at this place.
QString valueProblem(const QJsonValue &value, int depth, int items) {
    if (depth > L::kMaxDepth)
        return QStringLiteral("nested more than %1 deep").arg(L::kMaxDepth);
    if (value.isString() && value.toString().size() > L::kMaxStringChars)
        return QStringLiteral("a text of %1 characters (at most %2)")
            .arg(value.toString().size())
            .arg(L::kMaxStringChars);
    if (value.isArray()) {
        const QJsonArray array = value.toArray();
        if (array.size() > items)
            return QStringLiteral("a list of %1 items (at most %2)").arg(array.size()).arg(items);
        for (const QJsonValue &item : array)
            if (QString why = valueProblem(item, depth + 1, L::kMaxItems); !why.isEmpty())
                return why;
    }
    if (value.isObject()) {
        const QJsonObject object = value.toObject();
        if (object.size() > L::kMaxItems)
            return QStringLiteral("an object of %1 members (at most %2)")
                .arg(object.size())
                .arg(L::kMaxItems);
        for (auto it = object.begin(); it != object.end(); ++it) {
            if (it.key().size() > L::kMaxStringChars)
                return QStringLiteral("a key of %1 characters").arg(it.key().size());
            // Only a live batch's samples may be many.
            const int bound = it.key() == QLatin1String("samples") ? L::kMaxSamples : L::kMaxItems;
            if (QString why = valueProblem(it.value(), depth + 1, bound); !why.isEmpty())
                return why;
        }
    }
    return {};
}

qsizetype sizeBound(const QString &leaf) {
    if (leaf.endsWith(QLatin1String("/live")))
        return L::kMaxLiveBytes;
    if (leaf == QLatin1String("joint"))
        return L::kMaxJointBytes;
    return L::kMaxMessageBytes;
}

} // namespace

QString watchedMessageProblem(const QString &leaf, const QByteArray &payload, QJsonObject *json) {
    // Measured before it is parsed: a 6 MB message costs its reading, not its parsing.
    if (const qsizetype bound = sizeBound(leaf); payload.size() > bound)
        return QStringLiteral("%1: %2 bytes (at most %3)")
            .arg(base::elided(leaf))
            .arg(payload.size())
            .arg(bound);
    if (leaf.startsWith(QLatin1String("port/"))) {
        bool ok = false;
        const int port = leaf.section(QLatin1Char('/'), 1, 1).toInt(&ok);
        if (!ok || port < 1 || port > L::kMaxPorts)
            return QStringLiteral("%1: ports are numbered 1 to %2")
                .arg(base::elided(leaf))
                .arg(L::kMaxPorts);
    }
    *json = QJsonDocument::fromJson(payload).object();
    if (leaf == QLatin1String("info") &&
        json->value(QStringLiteral("ports")).toArray().size() > L::kMaxPorts)
        return QStringLiteral("info: %1 ports (at most %2)")
            .arg(json->value(QStringLiteral("ports")).toArray().size())
            .arg(L::kMaxPorts);
    if (leaf.endsWith(QLatin1String("/live"))) {
        const QJsonArray samples = json->value(QStringLiteral("samples")).toArray();
        for (const QJsonValue &sample : samples.isEmpty() ? QJsonArray{*json} : samples)
            if (sample.toObject().size() > L::kMaxSampleMembers)
                return QStringLiteral("%1: a sample of %2 values (at most %3)")
                    .arg(base::elided(leaf))
                    .arg(sample.toObject().size())
                    .arg(L::kMaxSampleMembers);
    }
    if (const QString why = valueProblem(*json, 0, L::kMaxItems); !why.isEmpty())
        return base::elided(leaf) + QStringLiteral(": ") + why;
    return {};
}

} // namespace tipscope::plant
