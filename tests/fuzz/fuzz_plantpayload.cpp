// Fuzz target: what a watching window reads from the plant's broker (PlantWatch), through the
// bounds of plantwatchlimits.h.
//
// The input is a topic's leaf ("info", "port/1/live", "joint" ...), a newline, and the payload.
// Besides "no crash, no sanitizer report": a refusal says why and quotes at most a cut leaf; an
// accepted message is within its size bound, names a port from 1 to kMaxPorts, and holds no text
// longer, no list longer and nothing deeper than the bounds, so what a watcher keeps of it is
// bounded whatever a publisher sends.
#include "fuzzcheck.h"

#include "plant/plantwatchlimits.h"

#include <QJsonArray>

using namespace tipscope::plant;
using L = PlantWatchLimits;

namespace {

// The bounds, checked again independently of how watchedMessageProblem() checks them.
bool bounded(const QJsonValue &value, int depth) {
    if (depth > L::kMaxDepth)
        return false;
    if (value.isString())
        return value.toString().size() <= L::kMaxStringChars;
    if (value.isArray()) {
        for (const QJsonValue &item : value.toArray())
            if (!bounded(item, depth + 1))
                return false;
        return value.toArray().size() <= L::kMaxSamples;
    }
    if (value.isObject()) {
        const QJsonObject object = value.toObject();
        for (auto it = object.begin(); it != object.end(); ++it)
            if (it.key().size() > L::kMaxStringChars || !bounded(it.value(), depth + 1))
                return false;
        return object.size() <= L::kMaxItems;
    }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const QByteArray input(reinterpret_cast<const char *>(data), qsizetype(size));
    const qsizetype newline = input.indexOf('\n');
    const QString leaf = QString::fromUtf8(input.left(qMax<qsizetype>(newline, 0)));
    const QByteArray payload = newline < 0 ? input : input.mid(newline + 1);
    QJsonObject json;
    const QString why = watchedMessageProblem(leaf, payload, &json);
    if (!why.isEmpty()) {
        FUZZ_CHECK(why.size() < 400);
        return 0;
    }
    FUZZ_CHECK(payload.size() <= L::kMaxLiveBytes);
    if (!leaf.endsWith(QLatin1String("/live")))
        FUZZ_CHECK(payload.size() <= L::kMaxMessageBytes);
    if (leaf.startsWith(QLatin1String("port/"))) {
        const int port = leaf.section(QLatin1Char('/'), 1, 1).toInt();
        FUZZ_CHECK(port >= 1 && port <= L::kMaxPorts);
    }
    FUZZ_CHECK(bounded(json, 0));
    FUZZ_CHECK(json.value(QStringLiteral("ports")).toArray().size() <= L::kMaxPorts ||
               leaf != QLatin1String("info"));
    return 0;
}
