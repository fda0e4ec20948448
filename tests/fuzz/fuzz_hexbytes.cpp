// Fuzz target: parseHexBytes, the hex reader behind the console's "send raw frame" field and
// `tipscope-cli send`.
//
// Input layout: byte 0 picks how the rest becomes text (UTF-8, Latin-1, or raw UTF-16 units, which
// reaches lone surrogates and characters outside Latin-1); the rest is what a person typed.
// Besides "no crash, no sanitizer report": a refusal always says why; an accepted text gives
// 1 to kMaxHexInputBytes bytes that print back (toHexText) as a text parsing to the same bytes;
// and toAsciiText works on any bytes.
#include "fuzzcheck.h"

#include "protocol/hexbytes.h"

using namespace tipscope::protocol;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 1)
        return 0;
    const char *rest = reinterpret_cast<const char *>(data + 1);
    const qsizetype n = qsizetype(size - 1);
    QString text;
    switch (data[0] % 3) {
    case 0:
        text = QString::fromUtf8(rest, n);
        break;
    case 1:
        text = QString::fromLatin1(rest, n);
        break;
    default:
        text = QString(reinterpret_cast<const QChar *>(rest), n / 2);
        break;
    }
    const auto bytes = parseHexBytes(text);
    if (!bytes.ok()) {
        FUZZ_CHECK(!bytes.error().isEmpty());
        return 0;
    }
    FUZZ_CHECK(!bytes->isEmpty() && bytes->size() <= kMaxHexInputBytes);
    const auto again = parseHexBytes(toHexText(*bytes));
    FUZZ_CHECK(again.ok() && again.value() == bytes.value());
    (void)toAsciiText(*bytes);
    (void)toAsciiText(QByteArray(rest, n));
    return 0;
}
