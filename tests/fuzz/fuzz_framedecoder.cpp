// Fuzz target: the streaming FrameDecoder, fed in arbitrary chunks.
//
// Input layout: byte 0 picks the decoder's maxFrameSize (8..71), byte 1 seeds the chunk lengths,
// the rest is the byte stream as a serial line might deliver it. Besides "no crash, no sanitizer
// report", the decoder's documented contract must hold for every input:
//  - every byte fed ends in exactly one event or is still pending (nothing lost, nothing doubled);
//  - memory stays bounded: no event and no pending candidate exceeds maxFrameSize + 1 bytes;
//  - a Frame event re-encodes to exactly its raw bytes, and parseFrame() agrees with the decoder;
//  - chunking changes nothing but where garbage is split: the same stream fed in one piece
//    yields the same frames and rejected candidates, in the same order.
#include "fuzzcheck.h"

#include "protocol/framedecoder.h"
#include "protocol/hexbytes.h"

#include <vector>

using namespace tipscope::protocol;

namespace {

struct Decoded {
    std::vector<DecodeEvent> candidates; // everything but garbage
    QByteArray garbage;
    qint64 accounted = 0;
};

void collect(Decoded &out, std::vector<DecodeEvent> &&events, int maxFrameSize) {
    for (DecodeEvent &e : events) {
        FUZZ_CHECK(!e.raw.isEmpty());
        FUZZ_CHECK(e.raw.size() <= maxFrameSize + 1);
        FUZZ_CHECK(!decodeEventKindName(e.kind).isEmpty());
        out.accounted += e.raw.size();
        if (e.kind == DecodeEvent::Kind::Garbage) {
            out.garbage += e.raw;
            continue;
        }
        if (e.kind == DecodeEvent::Kind::Frame) {
            FUZZ_CHECK(e.frame.encode() == e.raw);
            FUZZ_CHECK(e.frame.command.size() == 3);
            FUZZ_CHECK(e.frame.source.has_value() == e.frame.target.has_value());
            const auto again = parseFrame(e.raw);
            FUZZ_CHECK(again && *again == e.frame);
            (void)e.frame.toString();
        } else {
            FUZZ_CHECK(!e.detail.isEmpty());
            // A candidate rejected at its BCC byte must be rejected by parseFrame too.
            if (e.kind == DecodeEvent::Kind::BccError) {
                const auto again = parseFrame(e.raw);
                FUZZ_CHECK(!again && again.error().kind == e.kind && !again.error().why.isEmpty());
            }
        }
        (void)toAsciiText(e.raw);
        out.candidates.push_back(std::move(e));
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 2)
        return 0;
    const int maxFrameSize = 8 + data[0] % 64;
    std::uint32_t chunkSeed = data[1] | 1u;
    const QByteArrayView stream(reinterpret_cast<const char *>(data + 2), qsizetype(size - 2));

    FrameDecoder chunked(maxFrameSize);
    Decoded a;
    qsizetype pos = 0;
    while (pos < stream.size()) {
        // xorshift: lengths of 1 to 16 bytes, mostly short, like reads from a slow serial line.
        chunkSeed ^= chunkSeed << 13;
        chunkSeed ^= chunkSeed >> 17;
        chunkSeed ^= chunkSeed << 5;
        const qsizetype len = qMin<qsizetype>(1 + chunkSeed % 16, stream.size() - pos);
        collect(a, chunked.feed(stream.sliced(pos, len)), maxFrameSize);
        pos += len;
        FUZZ_CHECK(chunked.pendingBytes() <= maxFrameSize + 1);
        FUZZ_CHECK(a.accounted + chunked.pendingBytes() == pos);
    }

    FrameDecoder whole(maxFrameSize);
    Decoded b;
    collect(b, whole.feed(stream), maxFrameSize);
    FUZZ_CHECK(b.accounted + whole.pendingBytes() == stream.size());
    FUZZ_CHECK(whole.pendingBytes() == chunked.pendingBytes());
    FUZZ_CHECK(a.garbage == b.garbage);
    FUZZ_CHECK(a.candidates.size() == b.candidates.size());
    for (std::size_t i = 0; i < a.candidates.size(); ++i) {
        FUZZ_CHECK(a.candidates[i].kind == b.candidates[i].kind);
        FUZZ_CHECK(a.candidates[i].raw == b.candidates[i].raw);
    }

    // After reset() the decoder starts clean: a good frame that fits decodes as a frame.
    chunked.reset();
    FUZZ_CHECK(chunked.pendingBytes() == 0);
    const QByteArray probe = Frame::read("SMN").addressed(0, 1).encode();
    const auto events = chunked.feed(probe);
    if (probe.size() <= maxFrameSize)
        FUZZ_CHECK(events.size() == 1 && events.front().kind == DecodeEvent::Kind::Frame);
    return 0;
}
