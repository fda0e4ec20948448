#include "clistop.h"

#include <QEventLoop>
#include <QTimer>
#include <atomic>
#include <csignal>

namespace tipscope::cli {

namespace {
std::atomic<bool> g_stop{false};

extern "C" void requestStop(int) {
    g_stop = true;
}
} // namespace

void catchStopSignals() {
    std::signal(SIGINT, requestStop);
    std::signal(SIGTERM, requestStop);
}

bool stopRequested() {
    return g_stop;
}

void quitLoopOnStop(QEventLoop &loop) {
    auto *check = new QTimer(&loop);
    QObject::connect(check, &QTimer::timeout, &loop, [&loop] {
        if (g_stop)
            loop.quit();
    });
    check->start(kStopCheckMs);
}

} // namespace tipscope::cli
