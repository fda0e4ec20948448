// sendNow: a TCP write that reaches the system at once.
//
// QAbstractSocket::write() switches the socket's write notifier on and off around every write,
// and each switch wakes the event loop for one more turn: a poll() of every socket the thread
// has, which with 32 lines in one window was two extra turns per request. sendNow() hands the
// bytes to the socket itself when nothing waits in Qt's buffer before them, and says how many
// the system took; the caller passes the rest to QAbstractSocket::write(), so the order holds,
// and any error (a peer gone, a full buffer) is left for Qt to meet and report as it does.
#pragma once

#include <QAbstractSocket>
#include <QByteArray>

namespace tipscope::link {

// The bytes of `bytes` the system took (0 when Qt still holds unsent bytes, or on any error).
[[nodiscard]] qsizetype sendNow(QAbstractSocket &socket, const QByteArray &bytes);

} // namespace tipscope::link
