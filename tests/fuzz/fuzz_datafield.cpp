// Fuzz target: the data-field parsers and the catalog-typed value codec.
//
// Input layout: byte 0 picks the parser, bytes 1 and 2 pick a family and a command of the
// builtin catalog (for the typed parsers), the rest is the field or the text a person typed.
// Data fields arrive from the wire (answers, profiles) and text from people (the CLI, editors),
// so besides "no crash, no sanitizer report" each parser must be consistent with its encoder:
//  - parseNumber / parseDelay / parseHex accept only what their encoder can give back;
//  - parseUserValue never yields a value that validate() and encodeWrite() disagree about, and a
//    written value reads back as itself (decodeAnswer of the encoded field);
//  - a delay typed by a person is a real number of hundredths or a special value.
#include "fuzzcheck.h"

#include "protocol/datafield.h"
#include "protocol/valuecodec.h"

#include <cstring>
#include <vector>

using namespace tipscope::protocol;

namespace {

struct Commands {
    std::vector<ResolvedCommand> writes;
    std::vector<ResolvedCommand> reads;
};

// Every concrete command of every family, expanded once: the catalog is immutable.
const Commands &commands() {
    static const Commands all = [] {
        Commands c;
        const Catalog &cat = Catalog::builtin();
        for (const QString &family : cat.familyNames()) {
            for (const ResolvedCommand &w : cat.expand(family, Direction::Write))
                c.writes.push_back(w);
            for (const ResolvedCommand &r : cat.expand(family, Direction::Read))
                c.reads.push_back(r);
        }
        return c;
    }();
    return all;
}

const ResolvedCommand &pick(const std::vector<ResolvedCommand> &list, std::uint8_t a,
                            std::uint8_t b) {
    return list[(std::size_t(a) << 8 | b) % list.size()];
}

bool printable(const QByteArray &field) {
    for (char c : field)
        if (c < 0x20 || c > 0x7e)
            return false;
    return true;
}

// What a write of `value` puts on the wire, and that it reads back as the same value.
void checkWrite(const ResolvedCommand &cmd, qint64 value) {
    const auto field = encodeWrite(cmd, value);
    FUZZ_CHECK(field.ok() == validate(cmd, value).isEmpty());
    if (!field) {
        FUZZ_CHECK(!field.error().isEmpty());
        return;
    }
    FUZZ_CHECK(printable(*field) && field->size() <= 32);
    const auto read = Catalog::builtin().resolve(cmd.family, cmd.code, Direction::Read);
    const ValueKind kind = cmd.spec->kind;
    if (!read || kind == ValueKind::Action || kind == ValueKind::Flags)
        return;
    const auto back = decodeAnswer(*read, *field);
    FUZZ_CHECK(back && !back->isText && back->number == value);
    (void)describeValue(*read, *back, Wording::Translated);
}

void checkUserValue(const ResolvedCommand &cmd, const QString &text) {
    const auto value = parseUserValue(cmd, text);
    if (!value) {
        FUZZ_CHECK(!value.error().isEmpty());
        return;
    }
    if (cmd.spec->kind == ValueKind::Delay && !cmd.spec->special.contains(int(*value)))
        FUZZ_CHECK(*value >= 0 && *value <= kDelayMaxCentis);
    checkWrite(cmd, *value);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 3)
        return 0;
    const QByteArray field(reinterpret_cast<const char *>(data + 3), qsizetype(size - 3));
    switch (data[0] % 7) {
    case 0:
        if (const auto n = parseNumber(field)) {
            FUZZ_CHECK(*n >= kNumberMin && *n <= kNumberMax);
            const auto again = encodeNumber(*n);
            FUZZ_CHECK(again && parseNumber(*again) == n);
        }
        break;
    case 1:
        if (const auto d = parseDelay(field)) {
            FUZZ_CHECK(*d >= 0 && *d <= kDelayMaxCentis);
            FUZZ_CHECK(encodeDelay(*d) == field);
        }
        break;
    case 2:
        if (const auto h = parseHex(field))
            FUZZ_CHECK(parseHex(encodeHex(*h, 16)) == h);
        break;
    case 3:
        if (const auto t = parseText(field))
            FUZZ_CHECK(t->size() <= field.size());
        break;
    case 4:
        checkUserValue(pick(commands().writes, data[1], data[2]), QString::fromUtf8(field));
        break;
    case 5: {
        const ResolvedCommand &cmd = pick(commands().reads, data[1], data[2]);
        if (const auto v = decodeAnswer(cmd, field))
            (void)describeValue(cmd, *v, Wording::Catalog);
        break;
    }
    default: {
        qint64 value = 0;
        std::memcpy(&value, field.constData(), qMin<std::size_t>(sizeof value, field.size()));
        checkWrite(pick(commands().writes, data[1], data[2]), value);
        break;
    }
    }
    return 0;
}
