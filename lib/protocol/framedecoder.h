// FrameDecoder: turns an arbitrary stream of byte chunks into frames and decode errors.
//
// Feed it whatever the transport delivered (a frame split over several reads, several frames in
// one read, garbage in between). It never throws and never stalls: every byte ends up in exactly
// one event, either part of a good frame, part of a rejected candidate, or skipped garbage.
// The byte after ETX is always taken as the BCC, so a BCC equal to STX or ETX is handled. A
// candidate longer than maxFrameSize is reported as an overflow and dropped, which bounds memory.
// Each rejected candidate and each run of garbage is counted and logged (tipscope.protocol).
#pragma once

#include "base/outcome.h"
#include "frame.h"

#include <QByteArrayView>
#include <vector>

namespace tipscope::protocol {

struct DecodeEvent {
    enum class Kind { Frame, BccError, FormatError, Overflow, Garbage };
    Kind kind = Kind::Frame;
    Frame frame;    // valid when kind == Frame
    QByteArray raw; // the bytes this event accounts for
    QString detail; // why a candidate was rejected
};

[[nodiscard]] QString decodeEventKindName(DecodeEvent::Kind kind);

// Why a candidate is not a frame: the kind of event the decoder reports it as, and the reason.
struct DecodeFailure {
    DecodeEvent::Kind kind = DecodeEvent::Kind::FormatError;
    QString why;
};

// Parses the bytes of one complete candidate (STX ... ETX BCC), or says why it is not a frame.
[[nodiscard]] base::Outcome<Frame, DecodeFailure> parseFrame(const QByteArray &raw);

class FrameDecoder {
public:
    static constexpr int kDefaultMaxFrameSize = 64;

    explicit FrameDecoder(int maxFrameSize = kDefaultMaxFrameSize);

    [[nodiscard]] std::vector<DecodeEvent> feed(QByteArrayView chunk);
    void reset();
    [[nodiscard]] int pendingBytes() const { return int(m_candidate.size() + m_garbage.size()); }
    // Malformed candidates and runs of garbage skipped since construction (reset() keeps it).
    [[nodiscard]] qint64 skipped() const { return m_skipped; }

private:
    enum class State { Idle, InFrame, AwaitBcc };

    void logSkipped(const DecodeEvent &e);
    void flushGarbage(std::vector<DecodeEvent> &out);
    void finishCandidate(std::vector<DecodeEvent> &out);
    void emitRejected(std::vector<DecodeEvent> &out, DecodeEvent::Kind kind, const QString &why);

    int m_maxFrameSize;
    State m_state = State::Idle;
    QByteArray m_candidate;
    QByteArray m_garbage;
    qint64 m_skipped = 0;
};

} // namespace tipscope::protocol
