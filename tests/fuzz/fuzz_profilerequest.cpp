// Fuzz target: ProfileRequest::parse, what the agent reads from the broker before it applies a
// profile to a station (remote apply).
//
// The input is the message's payload. Besides "no crash, no sanitizer report": a refusal says
// why; an accepted request is within the profile's size bound, gives no key of its wrapper twice
// and none in its profile, carries a request id that is short and printable, and holds a profile
// that meets the file's own checks and survives a save/load round trip.
#include "fuzzcheck.h"

#include "model/profiles/profilejson.h"
#include "model/profiles/profilerequest.h"

using namespace tipscope::model;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const QByteArray payload(reinterpret_cast<const char *>(data), qsizetype(size));
    (void)profilejson::topLevelMembers(payload); // also on text that is not JSON: no overrun
    const auto request = ProfileRequest::parse(payload);
    FUZZ_CHECK(request.requestId.size() <= kMaxRequestIdLength);
    for (const QChar c : request.requestId)
        FUZZ_CHECK(c.category() != QChar::Other_Control);
    if (!request.profile.ok()) {
        FUZZ_CHECK(!request.profile.error().isEmpty());
        return 0;
    }
    FUZZ_CHECK(payload.size() <= kMaxProfileBytes);
    // Each key of the wrapper once, and nothing given twice in the profile that was sent.
    QStringList keys;
    for (const profilejson::Member &member : profilejson::topLevelMembers(payload)) {
        FUZZ_CHECK(!keys.contains(member.key));
        keys.append(member.key);
        if (member.key == QLatin1String("profile"))
            FUZZ_CHECK(profilejson::duplicateKeys(member.value).isEmpty());
    }
    const Profile &profile = *request.profile;
    FUZZ_CHECK(!profile.family.isEmpty() && !profile.values.isEmpty());
    FUZZ_CHECK(profile.problemsFor(profile.family).isEmpty());
    FUZZ_CHECK(Profile::fromJson(profile.toJson()).ok());
    return 0;
}
