// LateAnswers: which requests may still get a late answer, so that the request queue holds back
// the requests such an answer would be taken for.
//
// The robot protocol has no sequence numbers: an answer is matched to the open request by its
// command and addresses alone. When a request timed out, its answer may still be on its way, and
// if another request of the same command to the same device were sent meanwhile, the late answer
// would be taken for it (a read-back would report the value from before a write). So each
// timeout adds one answer still expected to a hold on that command and device, and pushes its
// deadline out; every stray answer of that command from that device is one of them arriving
// (and being discarded), and the hold ends when none is expected any more or at the deadline,
// when the rest are taken as lost. Holds end by themselves, so the bookkeeping stays bounded by
// the commands in use.
#pragma once

#include "protocol/frame.h"

#include <QByteArray>
#include <optional>
#include <vector>

namespace tipscope::link {

class LateAnswers {
public:
    // One more request of `command` to `device` (none: the mode without addresses) may still be
    // answered, until `untilMs`.
    void expect(const QByteArray &command, std::optional<int> device, qint64 untilMs);
    [[nodiscard]] bool holds(const QByteArray &command, std::optional<int> device,
                             qint64 nowMs) const;
    // `stray` matched no open request; returns true when it was a late answer a hold expected.
    bool absorb(const protocol::Frame &stray, int robotAddress);
    // The earliest deadline still ahead of `nowMs`, after dropping the holds that have passed.
    [[nodiscard]] std::optional<qint64> nextDeadline(qint64 nowMs);

private:
    struct Hold {
        QByteArray command;
        std::optional<int> device;
        qint64 untilMs = 0;
        int expected = 0; // answers still to come
    };
    std::vector<Hold> m_holds;
};

} // namespace tipscope::link
