#include "socketsend.h"

#ifdef Q_OS_UNIX
#include <cerrno>
#include <sys/socket.h>
#endif

namespace tipscope::link {

qsizetype sendNow(QAbstractSocket &socket, const QByteArray &bytes) {
#ifdef Q_OS_UNIX
    const int fd = int(socket.socketDescriptor());
    if (fd < 0 || socket.bytesToWrite() > 0 || socket.state() != QAbstractSocket::ConnectedState)
        return 0;
    for (;;) {
        const ssize_t n =
            ::send(fd, bytes.constData(), size_t(bytes.size()), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n >= 0)
            return qsizetype(n);
        if (errno != EINTR)
            return 0;
    }
#else
    Q_UNUSED(socket);
    Q_UNUSED(bytes);
    return 0;
#endif
}

} // namespace tipscope::link
