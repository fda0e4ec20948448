// ProfileJson: what Profile::fromJson() checks in a profile's text beyond what QJsonDocument
// does, so that the file means exactly one thing.
//
// JSON allows no raw control character inside a string, yet QJsonDocument takes a NUL there
// ("tipscope-\0profile"), which then reads as another format. And an object may repeat a key:
// QJsonDocument keeps the last one silently, so `"ST1": "00300", "ST1": "00450"` or two
// "values" objects would apply only what a person did not notice. Both are refused, with the
// byte or the keys named. Codes in "values" are compared as the profile applies them (upper
// case), so "st1" and "ST1" are the same key.
#pragma once

#include <QByteArray>
#include <QStringList>

namespace tipscope::model::profilejson {

// Empty, or why `json` is not valid JSON: "a NUL byte at byte 31" (bytes counted from 1).
[[nodiscard]] QString controlCharacterProblem(const QByteArray &json);

// The keys given more than once in one object of `json`, which QJsonDocument must already have
// accepted: "ST1" for a code of "values", "values" at the top level, "a.b" deeper. Each once.
[[nodiscard]] QStringList duplicateKeys(const QByteArray &json);

// A member of the top-level object of `json`: its key and its value's exact bytes, so a nested
// document (a profile inside a request) can be checked as the text that was sent, not as what
// QJsonDocument kept of it.
struct Member {
    QString key;
    QByteArray value;
};

// The members of `json`'s top-level object in the order given, repeated keys included. `json`
// must be an object QJsonDocument has already accepted.
[[nodiscard]] QList<Member> topLevelMembers(const QByteArray &json);

} // namespace tipscope::model::profilejson
