#include "frame.h"

namespace tipscope::protocol {

std::optional<Header> headerFromChar(char c) {
    switch (c) {
    case 'R':
        return Header::Read;
    case 'W':
        return Header::Write;
    case 'A':
        return Header::Answer;
    case 'N':
        return Header::Nak;
    default:
        return std::nullopt;
    }
}

QString headerName(Header h) {
    switch (h) {
    case Header::Read:
        return QStringLiteral("Read");
    case Header::Write:
        return QStringLiteral("Write");
    case Header::Answer:
        return QStringLiteral("Answer");
    case Header::Nak:
        return QStringLiteral("NAK");
    }
    return {};
}

char blockCheck(const QByteArray &bytes) {
    char bcc = 0;
    for (char b : bytes)
        bcc ^= b;
    return bcc;
}

static QByteArray twoDigits(int address) {
    return QByteArray::number(address).rightJustified(2, '0');
}

QByteArray Frame::encode() const {
    QByteArray out;
    out.reserve(16 + data.size());
    out.append(kStx);
    if (isAddressed()) {
        out.append(twoDigits(*source));
        out.append(twoDigits(*target));
    }
    out.append(static_cast<char>(header));
    out.append(command);
    out.append(data);
    out.append(kEtx);
    out.append(blockCheck(out));
    return out;
}

QString Frame::toString() const {
    QString s;
    if (isAddressed())
        s = QStringLiteral("%1→%2 ")
                .arg(*source, 2, 10, QLatin1Char('0'))
                .arg(*target, 2, 10, QLatin1Char('0'));
    s += QLatin1Char(static_cast<char>(header));
    s += QLatin1Char(' ') + QString::fromLatin1(command);
    if (!data.isEmpty())
        s += QLatin1Char(' ') + QString::fromLatin1(data);
    return s;
}

Frame Frame::read(const QByteArray &command) {
    Frame f;
    f.header = Header::Read;
    f.command = command;
    return f;
}

Frame Frame::write(const QByteArray &command, const QByteArray &data) {
    Frame f;
    f.header = Header::Write;
    f.command = command;
    f.data = data;
    return f;
}

Frame Frame::addressed(int src, int tgt) const {
    Frame f = *this;
    f.source = src;
    f.target = tgt;
    return f;
}

bool operator==(const Frame &a, const Frame &b) {
    return a.source == b.source && a.target == b.target && a.header == b.header &&
           a.command == b.command && a.data == b.data;
}

} // namespace tipscope::protocol
