#include "xvfbserver.h"

#include <QByteArray>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace tipscope::testing {

namespace {

constexpr int kStartMs = 10000;

pid_t g_server = -1;

void stopServer() {
    if (g_server <= 0)
        return;
    ::kill(g_server, SIGTERM);
    int status = 0;
    ::waitpid(g_server, &status, 0);
    g_server = -1;
}

} // namespace

QString startXvfbDisplay(QSize screen) {
    if (g_server > 0)
        return QStringLiteral("an X server was already started");
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        return QStringLiteral("pipe: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
    const QByteArray geometry =
        QStringLiteral("%1x%2x24").arg(screen.width()).arg(screen.height()).toLatin1();
    const pid_t pid = ::fork();
    if (pid < 0)
        return QStringLiteral("fork: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
    if (pid == 0) {
        // A test that crashes takes its server with it.
        ::prctl(PR_SET_PDEATHSIG, SIGTERM);
        // The write end must survive exec: Xvfb writes its display number to it (-displayfd).
        const int out = ::dup(fds[1]);
        const QByteArray fd = QByteArray::number(out);
        ::execlp("Xvfb", "Xvfb", "-displayfd", fd.constData(), "-screen", "0", geometry.constData(),
                 "-nolisten", "tcp", "-noreset", static_cast<char *>(nullptr));
        ::_exit(127);
    }
    ::close(fds[1]);
    g_server = pid;
    std::atexit(stopServer);
    QByteArray display;
    pollfd wait{fds[0], POLLIN, 0};
    while (!display.endsWith('\n') && ::poll(&wait, 1, kStartMs) > 0) {
        char c = 0;
        if (::read(fds[0], &c, 1) != 1)
            break;
        display.append(c);
    }
    ::close(fds[0]);
    display = display.trimmed();
    if (display.isEmpty()) {
        int status = 0;
        const bool ended = ::waitpid(pid, &status, WNOHANG) == pid;
        const bool missing = ended && WIFEXITED(status) && WEXITSTATUS(status) == 127;
        if (!ended)
            stopServer();
        g_server = -1;
        return missing ? QStringLiteral("Xvfb is not installed (scripts/install-deps installs it)")
                       : QStringLiteral("Xvfb did not say which display it serves within %1 ms")
                             .arg(kStartMs);
    }
    qputenv("DISPLAY", ":" + display);
    qputenv("QT_QPA_PLATFORM", "xcb");
    return {};
}

} // namespace tipscope::testing
