// ProfileRequest: a profile sent from another machine to be applied (remote apply through the
// broker, docs/mqtt.md), read by exactly the parser and checks of a profile file.
//
// A request is the profile file itself, or {"request_id": "...", "profile": {...}}. The wrapper
// may not weaken what a file must meet: the whole request has the file's bound (1 MiB), no raw
// control character and no key given twice (two "profile" objects are refused, not the last one
// applied), and the profile inside goes to Profile::fromJson() as the bytes that were sent, so a
// code given twice in it is refused by name as in a file (QJsonDocument alone keeps the last).
// The request id is echoed in the answer and kept in the journal, so it is bounded and printable.
#pragma once

#include "profile.h"

namespace tipscope::model {

inline constexpr int kMaxRequestIdLength = 128;

struct ProfileRequest {
    // The request's id when it gave a usable one, also when its profile is refused, so that the
    // answer can carry it. Empty otherwise.
    QString requestId;
    // The profile, or why the request is refused (nothing of it is to be written).
    base::Outcome<Profile> profile{base::failure(QStringLiteral("no request read"))};

    [[nodiscard]] static ProfileRequest parse(const QByteArray &payload);
};

} // namespace tipscope::model
