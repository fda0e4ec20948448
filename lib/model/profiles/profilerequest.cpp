#include "profilerequest.h"

#include "profilejson.h"

#include "base/elide.h"

#include <QCoreApplication>
#include <QHash>
#include <QJsonDocument>
#include <QJsonObject>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {

struct ProfileRequestTr {
    Q_DECLARE_TR_FUNCTIONS(ProfileRequest)
};

const QString kProfileKey = QStringLiteral("profile");
const QString kRequestIdKey = QStringLiteral("request_id");

bool isPrintable(const QString &text) {
    for (const QChar c : text)
        if (c.category() == QChar::Other_Control || c.category() == QChar::Other_Format)
            return false;
    return true;
}

// Empty, or why the id cannot be echoed: it goes into the answer and the journal.
QString requestIdProblem(const QJsonValue &id) {
    if (id.isUndefined())
        return {};
    if (!id.isString() || id.toString().size() > kMaxRequestIdLength || !isPrintable(id.toString()))
        return ProfileRequestTr::tr("\"request_id\" must be text of at most %1 characters, "
                                    "without control characters")
            .arg(kMaxRequestIdLength);
    return {};
}

} // namespace

ProfileRequest ProfileRequest::parse(const QByteArray &payload) {
    ProfileRequest request;
    const auto refuse = [&request](const QString &why) {
        request.profile = base::failure(why);
        return request;
    };
    // Measured before anything is parsed: an oversized request costs no more than its reading.
    if (const QString why = Profile::sizeProblem(payload.size()); !why.isEmpty())
        return refuse(ProfileRequestTr::tr("the request is %1; nothing will be written").arg(why));
    const QJsonDocument doc = QJsonDocument::fromJson(payload);
    const QJsonObject root = doc.object();
    // A profile as it is, and whatever is not a well-formed wrapper, meet the file's own checks
    // and messages (a NUL byte, invalid JSON, not a profile).
    if (!root.contains(kProfileKey) || !profilejson::controlCharacterProblem(payload).isEmpty()) {
        request.profile = Profile::fromJson(payload);
        return request;
    }
    QHash<QString, int> seen;
    QStringList twice;
    QByteArray profileText;
    for (const profilejson::Member &member : profilejson::topLevelMembers(payload)) {
        if (++seen[member.key] == 2)
            twice.append(base::elided(member.key));
        if (member.key == kProfileKey)
            profileText = member.value;
    }
    if (!twice.isEmpty())
        return refuse(ProfileRequestTr::tr("given more than once, so which one is meant is "
                                           "unclear: %1; nothing will be written")
                          .arg(twice.join(QLatin1String(", "))));
    if (const QString why = requestIdProblem(root.value(kRequestIdKey)); !why.isEmpty())
        return refuse(why);
    request.requestId = root.value(kRequestIdKey).toString();
    if (!root.value(kProfileKey).isObject())
        return refuse(ProfileRequestTr::tr("\"profile\" must be a profile: an object as "
                                           "tipscope-cli profile save writes it"));
    request.profile = Profile::fromJson(profileText);
    return request;
}

} // namespace tipscope::model
