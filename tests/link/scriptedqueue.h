// ScriptedQueue: a RequestQueue on an open ScriptedTransport, for tests of what a queue reports
// (its statistics, its tap) rather than of the queue itself.
#pragma once

#include "scriptedtransport.h"

#include "link/requestqueue.h"

namespace tipscope::test {

struct ScriptedQueue {
    // `retries` and `turnaroundMs` as the test needs them; the rest as a line would have it.
    ScriptedQueue(int retries, int turnaroundMs) {
        link::QueueSettings settings;
        settings.retries = retries;
        settings.turnaroundMs = turnaroundMs;
        queue.setSettings(settings);
        queue.setTransport(&transport);
        queue.lineOpened();
    }

    ScriptedTransport transport;
    link::RequestQueue queue;
};

} // namespace tipscope::test
