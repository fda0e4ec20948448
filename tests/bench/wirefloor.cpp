#include "wirefloor.h"

#include "processactivity.h"

#include "protocol/catalog.h"
#include "protocol/frame.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/epoll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>
#include <utility>

namespace tipscope::bench {

namespace {

constexpr int kConnectTimeoutMs = 5000;
constexpr int kWaitSliceMs = 100;

// A file descriptor closed with its owner.
class Fd {
public:
    explicit Fd(int fd = -1)
        : m_fd(fd) {}
    ~Fd() {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    Fd(Fd &&other) noexcept
        : m_fd(std::exchange(other.m_fd, -1)) {}
    Fd &operator=(Fd &&) = delete;
    Fd(const Fd &) = delete;
    Fd &operator=(const Fd &) = delete;
    [[nodiscard]] int get() const { return m_fd; }

private:
    int m_fd;
};

// One line: its socket and whether the ETX of the answer it waits for has arrived.
struct FloorLine {
    Fd socket;
    bool sawEtx = false;
};

QByteArray floorRequest() {
    const protocol::Catalog &catalog = protocol::Catalog::builtin();
    const auto tip = catalog.resolve(QStringLiteral("DME"), protocol::Role::TipTemperature, 1,
                                     protocol::Direction::Read);
    Q_ASSERT(tip);
    return protocol::Frame::read(tip->code)
        .addressed(catalog.address(QStringLiteral("robot")),
                   catalog.address(QStringLiteral("station")))
        .encode();
}

qint64 threadCpuUs(bool userOnly = false) {
    rusage r{};
    ::getrusage(RUSAGE_THREAD, &r);
    const qint64 user = qint64(r.ru_utime.tv_sec) * 1000000 + r.ru_utime.tv_usec;
    return userOnly ? user : user + qint64(r.ru_stime.tv_sec) * 1000000 + r.ru_stime.tv_usec;
}

// A connected non-blocking socket to host:port, or an invalid Fd with `error` set.
Fd connectTo(const QString &address, QString *error) {
    const QByteArray host = address.section(QLatin1Char(':'), 0, 0).toLatin1();
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(quint16(address.section(QLatin1Char(':'), 1).toUInt()));
    Fd fd(::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
    if (fd.get() < 0 || ::inet_pton(AF_INET, host.constData(), &to.sin_addr) != 1) {
        *error = QStringLiteral("%1: no socket or not an IPv4 address").arg(address);
        return Fd();
    }
    const int one = 1; // a request must not wait for Nagle's algorithm, as in the link
    ::setsockopt(fd.get(), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    if (::connect(fd.get(), reinterpret_cast<const sockaddr *>(&to), sizeof to) != 0 &&
        errno != EINPROGRESS) {
        *error = QStringLiteral("%1: %2").arg(address, QString::fromLocal8Bit(strerror(errno)));
        return Fd();
    }
    pollfd writable{fd.get(), POLLOUT, 0};
    int soError = 0;
    socklen_t length = sizeof soError;
    if (::poll(&writable, 1, kConnectTimeoutMs) != 1 ||
        ::getsockopt(fd.get(), SOL_SOCKET, SO_ERROR, &soError, &length) != 0 || soError != 0) {
        *error = QStringLiteral("%1: could not connect").arg(address);
        return Fd();
    }
    return fd;
}

// Consumes what arrived on a line; true when it completed the answer being waited for.
bool answerCompleted(FloorLine &line) {
    char bytes[512];
    bool completed = false;
    for (;;) {
        const ssize_t n = ::read(line.socket.get(), bytes, sizeof bytes);
        if (n <= 0)
            return completed;
        for (ssize_t i = 0; i < n; ++i) {
            if (line.sawEtx) { // this byte is the block check
                line.sawEtx = false;
                completed = true;
            } else if (bytes[i] == protocol::kEtx) {
                line.sawEtx = true;
            }
        }
        if (n < ssize_t(sizeof bytes))
            return completed;
    }
}

} // namespace

std::optional<WireFloor> measureWireFloor(const std::vector<SimStation> &stations, int ms,
                                          QString *error) {
    const QByteArray request = floorRequest();
    Fd epoll(::epoll_create1(EPOLL_CLOEXEC));
    std::vector<FloorLine> lines;
    lines.reserve(stations.size());
    for (const SimStation &station : stations) {
        Fd socket = connectTo(station.address, error);
        if (socket.get() < 0)
            return std::nullopt;
        epoll_event interest{};
        interest.events = EPOLLIN;
        interest.data.u64 = lines.size();
        ::epoll_ctl(epoll.get(), EPOLL_CTL_ADD, socket.get(), &interest);
        lines.push_back({std::move(socket), false});
    }
    const auto send = [&](const FloorLine &line) {
        (void)::send(line.socket.get(), request.constData(), size_t(request.size()),
                     MSG_NOSIGNAL | MSG_DONTWAIT);
    };
    for (const FloorLine &line : lines)
        send(line);

    qint64 answered = 0;
    const ProcessActivity activity(::getpid(), ::gettid());
    const qint64 cpuBefore = threadCpuUs(), userBefore = threadCpuUs(true);
    QElapsedTimer wall;
    wall.start();
    epoll_event ready[64];
    while (wall.elapsed() < ms) {
        const int n = ::epoll_wait(epoll.get(), ready, int(std::size(ready)), kWaitSliceMs);
        for (int i = 0; i < n; ++i) {
            FloorLine &line = lines[size_t(ready[i].data.u64)];
            if (answerCompleted(line)) {
                ++answered;
                send(line);
            }
        }
    }
    const double seconds = double(wall.elapsed()) / 1000;
    const qint64 cpuUs = threadCpuUs() - cpuBefore, userUs = threadCpuUs(true) - userBefore;
    const std::optional<qint64> syscalls = activity.syscalls();
    const qint64 wakeUps = activity.wakeUps();
    if (answered == 0) {
        *error = QStringLiteral("no station answered the floor's requests");
        return std::nullopt;
    }
    WireFloor floor;
    floor.txPerS = double(answered) / seconds;
    floor.cpuUsPerTx = double(cpuUs) / double(answered);
    floor.userUsPerTx = double(userUs) / double(answered);
    if (syscalls)
        floor.syscallsPerTx = double(*syscalls) / double(answered);
    floor.wakeUpsPerTx = double(wakeUps) / double(answered);
    return floor;
}

} // namespace tipscope::bench
