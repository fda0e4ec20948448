#include "framedecoder.h"
#include "frame.h"

#include "protocollogging.h"

#include <QCoreApplication>

namespace tipscope::protocol {

namespace {
struct FrameDecoderTr {
    Q_DECLARE_TR_FUNCTIONS(FrameDecoder)
};
} // namespace

QString decodeEventKindName(DecodeEvent::Kind kind) {
    switch (kind) {
    case DecodeEvent::Kind::Frame:
        return FrameDecoderTr::tr("frame");
    case DecodeEvent::Kind::BccError:
        return FrameDecoderTr::tr("BCC error");
    case DecodeEvent::Kind::FormatError:
        return FrameDecoderTr::tr("format error");
    case DecodeEvent::Kind::Overflow:
        return FrameDecoderTr::tr("overflow");
    case DecodeEvent::Kind::Garbage:
        return FrameDecoderTr::tr("garbage");
    }
    return {};
}

static bool isCommandChar(char c) {
    return isAsciiDigit(c) || (c >= 'A' && c <= 'Z');
}
static bool isPrintable(char c) {
    return c >= 0x20 && c <= 0x7e;
}

static base::Failure<DecodeFailure> fail(DecodeEvent::Kind kind, const QString &why) {
    return base::failure(DecodeFailure{kind, why});
}

base::Outcome<Frame, DecodeFailure> parseFrame(const QByteArray &raw) {
    using K = DecodeEvent::Kind;
    const qsizetype n = raw.size();
    if (n < 7 || raw.at(0) != kStx || raw.at(n - 2) != kEtx)
        return fail(K::FormatError, FrameDecoderTr::tr("not STX…ETX BCC or too short"));
    const char expected = blockCheck(raw.left(n - 1));
    if (expected != raw.at(n - 1))
        return fail(K::BccError, FrameDecoderTr::tr("BCC is %1, expected %2")
                                     .arg(quint8(raw.at(n - 1)), 2, 16, QLatin1Char('0'))
                                     .arg(quint8(expected), 2, 16, QLatin1Char('0')));

    const QByteArray body = raw.mid(1, n - 3);
    Frame f;
    qsizetype pos = 0;
    if (isAsciiDigit(body.at(0))) {
        if (body.size() < 8 || !isAsciiDigit(body.at(1)) || !isAsciiDigit(body.at(2)) ||
            !isAsciiDigit(body.at(3)))
            return fail(K::FormatError, FrameDecoderTr::tr("malformed addresses"));
        f.source = body.mid(0, 2).toInt();
        f.target = body.mid(2, 2).toInt();
        pos = 4;
    }
    if (body.size() < pos + 4)
        return fail(K::FormatError, FrameDecoderTr::tr("too short for header and command"));
    const auto header = headerFromChar(body.at(pos));
    if (!header)
        return fail(K::FormatError, FrameDecoderTr::tr("unknown header"));
    f.header = *header;
    f.command = body.mid(pos + 1, 3);
    for (char c : f.command)
        if (!isCommandChar(c))
            return fail(K::FormatError, FrameDecoderTr::tr("command is not 3 letters or digits"));
    f.data = body.mid(pos + 4);
    for (char c : f.data)
        if (!isPrintable(c))
            return fail(K::FormatError, FrameDecoderTr::tr("data field is not printable ASCII"));
    return f;
}

FrameDecoder::FrameDecoder(int maxFrameSize)
    : m_maxFrameSize(qMax(maxFrameSize, 8)) {}

void FrameDecoder::reset() {
    m_state = State::Idle;
    m_candidate.clear();
    m_garbage.clear();
}

std::vector<DecodeEvent> FrameDecoder::feed(QByteArrayView chunk) {
    std::vector<DecodeEvent> out;
    for (char byte : chunk) {
        switch (m_state) {
        case State::Idle:
            if (byte == kStx) {
                flushGarbage(out);
                m_candidate.append(byte);
                m_state = State::InFrame;
            } else {
                m_garbage.append(byte);
                if (m_garbage.size() >= m_maxFrameSize)
                    flushGarbage(out);
            }
            break;
        case State::InFrame:
            if (byte == kStx) {
                // A frame cannot contain STX: the candidate was cut short; restart here.
                emitRejected(out, DecodeEvent::Kind::FormatError,
                             FrameDecoderTr::tr("frame interrupted by a new STX"));
                m_candidate.append(byte);
                m_state = State::InFrame;
            } else {
                m_candidate.append(byte);
                if (byte == kEtx)
                    m_state = State::AwaitBcc;
                else if (m_candidate.size() > m_maxFrameSize - 1)
                    emitRejected(out, DecodeEvent::Kind::Overflow,
                                 FrameDecoderTr::tr("no ETX within %1 bytes").arg(m_maxFrameSize));
            }
            break;
        case State::AwaitBcc:
            m_candidate.append(byte);
            finishCandidate(out);
            break;
        }
    }
    flushGarbage(out);
    return out;
}

void FrameDecoder::logSkipped(const DecodeEvent &e) {
    ++m_skipped;
    qCDebug(lcProtocol).noquote() << "skipped" << decodeEventKindName(e.kind) << '#' << m_skipped
                                  << "(" << e.detail << "):" << e.raw.toHex(' ');
}

void FrameDecoder::flushGarbage(std::vector<DecodeEvent> &out) {
    if (m_garbage.isEmpty())
        return;
    DecodeEvent e;
    e.kind = DecodeEvent::Kind::Garbage;
    e.raw = m_garbage;
    e.detail = FrameDecoderTr::tr("%n byte(s) outside any frame", nullptr, int(m_garbage.size()));
    logSkipped(e);
    out.push_back(std::move(e));
    m_garbage.clear();
}

void FrameDecoder::finishCandidate(std::vector<DecodeEvent> &out) {
    auto frame = parseFrame(m_candidate);
    if (!frame) {
        const DecodeFailure f = frame.error();
        emitRejected(out, f.kind, f.why);
        return;
    }
    DecodeEvent e;
    e.kind = DecodeEvent::Kind::Frame;
    e.frame = std::move(frame).value();
    e.raw = m_candidate;
    out.push_back(std::move(e));
    m_candidate.clear();
    m_state = State::Idle;
}

void FrameDecoder::emitRejected(std::vector<DecodeEvent> &out, DecodeEvent::Kind kind,
                                const QString &why) {
    DecodeEvent e;
    e.kind = kind;
    e.raw = m_candidate;
    e.detail = why;
    logSkipped(e);
    out.push_back(std::move(e));
    m_candidate.clear();
    m_state = State::Idle;
}

} // namespace tipscope::protocol
