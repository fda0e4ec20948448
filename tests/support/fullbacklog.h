// FullBacklog: a TCP listener on the loopback interface whose accept queue is full. It never
// accepts, and the connections that filled its queue stay open, so the kernel drops every further
// SYN and a new connect() just waits, as with a serial device server that is overwhelmed or a
// host that swallows the packets.
#pragma once

#include <QList>

namespace tipscope::testing {

class FullBacklog {
public:
    FullBacklog();
    ~FullBacklog();
    FullBacklog(const FullBacklog &) = delete;
    FullBacklog &operator=(const FullBacklog &) = delete;
    // 0 when the listener could not be set up.
    [[nodiscard]] quint16 port() const { return m_port; }

private:
    int m_listener = -1;
    quint16 m_port = 0;
    QList<int> m_fillers;
};

} // namespace tipscope::testing
