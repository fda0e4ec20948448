#include "fullbacklog.h"

#include <QThread>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace tipscope::testing {

namespace {
constexpr int kFillers = 4; // a backlog of 0 still queues one connection; more to be sure
constexpr int kHandshakeMs = 200;
} // namespace

FullBacklog::FullBacklog() {
    m_listener = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof a;
    auto *addr = reinterpret_cast<sockaddr *>(&a);
    if (m_listener < 0 || ::bind(m_listener, addr, len) != 0 || ::listen(m_listener, 0) != 0 ||
        ::getsockname(m_listener, addr, &len) != 0)
        return;
    for (int i = 0; i < kFillers; ++i) {
        const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
        (void)::connect(fd, addr, sizeof a); // in progress: completes only while queue has room
        m_fillers.append(fd);
    }
    QThread::msleep(kHandshakeMs); // the handshakes that can complete, complete
    m_port = ntohs(a.sin_port);
}

FullBacklog::~FullBacklog() {
    for (int fd : m_fillers)
        ::close(fd);
    if (m_listener >= 0)
        ::close(m_listener);
}

} // namespace tipscope::testing
