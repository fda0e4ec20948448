// Frame: one frame of the JBC robot protocol as a value.
//
// On the wire a frame is STX, optionally two 2-digit addresses (source then target), a one-letter
// header (R, W, A, N), a 3-character command, a data field (5 characters for numbers, any length
// for text answers, empty for reads and for some answers), ETX and a BCC that is the XOR of every
// byte from STX through ETX. A Frame holds the fields; encode() and FrameDecoder convert.
#pragma once

#include <QByteArray>
#include <QString>
#include <optional>

namespace tipscope::protocol {

inline constexpr char kStx = 0x02;
inline constexpr char kEtx = 0x03;
inline constexpr int kMaxAddress = 99;

// Command codes and data fields are ASCII: a digit is '0' to '9', whatever the locale.
[[nodiscard]] constexpr bool isAsciiDigit(char c) {
    return c >= '0' && c <= '9';
}

enum class Header : char { Read = 'R', Write = 'W', Answer = 'A', Nak = 'N' };

[[nodiscard]] std::optional<Header> headerFromChar(char c);
[[nodiscard]] QString headerName(Header h);

struct Frame {
    std::optional<int> source; // set in addressed mode (both or neither)
    std::optional<int> target;
    Header header = Header::Read;
    QByteArray command; // exactly 3 characters, e.g. "ST1"
    QByteArray data;    // the data field as sent, e.g. "00350"; may be empty

    [[nodiscard]] bool isAddressed() const { return source.has_value() && target.has_value(); }
    [[nodiscard]] QByteArray encode() const;
    // Human-readable one-liner for logs and the console: "00→01 W MAT 00375".
    [[nodiscard]] QString toString() const;

    [[nodiscard]] static Frame read(const QByteArray &command);
    [[nodiscard]] static Frame write(const QByteArray &command, const QByteArray &data);
    [[nodiscard]] Frame addressed(int source, int target) const;

    friend bool operator==(const Frame &a, const Frame &b);
    friend bool operator!=(const Frame &a, const Frame &b) { return !(a == b); }
};

// XOR of every byte of `bytes` (the caller passes STX through ETX).
[[nodiscard]] char blockCheck(const QByteArray &bytes);

} // namespace tipscope::protocol
