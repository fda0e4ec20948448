// Fuzz target: Profile::fromJson, the loader of profile files people copy between machines and
// edit by hand.
//
// The input is the file's content. Besides "no crash, no sanitizer report", the loader's
// contract must hold: a refused file says why; an accepted one names a known family, has at
// least one value, gives each code once, passes problemsFor() for its own family (so applying
// it cannot write a value the catalog refuses), and survives a save/load round trip with the
// same values. The hand-written key scan (profilejson.h) also runs on every input, valid JSON
// or not, so a malformed text cannot make it read out of bounds.
#include "fuzzcheck.h"

#include "model/profiles/profile.h"
#include "model/profiles/profilejson.h"

#include <QMap>

using namespace tipscope::model;

namespace {

QMap<QByteArray, QByteArray> valueMap(const Profile &p) {
    QMap<QByteArray, QByteArray> m;
    for (const auto &[code, data] : p.values)
        m.insert(code, data);
    return m;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const QByteArray json(reinterpret_cast<const char *>(data), qsizetype(size));
    const QStringList twice = profilejson::duplicateKeys(json);
    const auto profile = Profile::fromJson(json);
    if (!profile.ok()) {
        FUZZ_CHECK(!profile.error().isEmpty());
        return 0;
    }
    FUZZ_CHECK(!profile->family.isEmpty() && !profile->values.isEmpty());
    FUZZ_CHECK(twice.isEmpty());
    FUZZ_CHECK(valueMap(*profile).size() == profile->values.size()); // each code once
    FUZZ_CHECK(profile->problemsFor(profile->family).isEmpty());
    const auto reloaded = Profile::fromJson(profile->toJson());
    FUZZ_CHECK(reloaded.ok());
    FUZZ_CHECK(reloaded->family == profile->family);
    FUZZ_CHECK(valueMap(*reloaded) == valueMap(*profile));
    return 0;
}
