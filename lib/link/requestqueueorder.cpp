// The request queue's choice of what goes next: priorities, the fairness rule, coalescing of
// identical reads, and the holds that keep a late answer from being taken for the wrong request.
#include "requestqueue.h"

#include "transport.h"

namespace tipscope::link {

using namespace tipscope::protocol;

bool RequestQueue::tryCoalesce(const Request &r, Reply *reply) {
    if (r.header != Header::Read || !r.raw.isEmpty())
        return false;
    for (size_t p = 0; p < m_queues.size(); ++p) {
        auto &q = m_queues[p];
        for (auto it = q.begin(); it != q.end(); ++it) {
            const Request &o = it->request;
            if (o.header != Header::Read || !o.raw.isEmpty() || o.command != r.command ||
                o.target != r.target)
                continue;
            it->replies.append(reply);
            if (!it->request.format)
                it->request.format = r.format;
            ++m_stats.coalesced;
            if (size_t(r.priority) < p) { // the more urgent asker decides where it waits
                Entry moved = std::move(*it);
                q.erase(it);
                moved.request.priority = r.priority;
                m_queues[size_t(r.priority)].push_back(std::move(moved));
            }
            return true;
        }
    }
    return false;
}

int RequestQueue::pendingCount() const {
    int n = m_current ? 1 : 0;
    for (const auto &q : m_queues)
        n += int(q.size());
    return n;
}

void RequestQueue::sendNext() {
    if (m_state != State::Idle || !m_open || !m_transport || m_current)
        return;
    const auto hasWanted = [](const std::deque<Entry> &q) {
        return std::any_of(q.begin(), q.end(), [](const Entry &e) { return e.wanted(); });
    };
    const bool pollsWaiting = hasWanted(m_queues[size_t(Priority::LivePoll)]) ||
                              hasWanted(m_queues[size_t(Priority::Background)]);
    const bool pollsFirst = pollsWaiting && m_urgentRun >= m_settings.urgentBurst;
    const std::array<size_t, 4> order =
        pollsFirst ? std::array<size_t, 4>{2, 3, 0, 1} : std::array<size_t, 4>{0, 1, 2, 3};
    for (size_t p : order) {
        std::optional<Entry> e = takeSendable(m_queues[p], p == size_t(Priority::UserWrite));
        if (!e)
            continue;
        const bool urgent = p <= size_t(Priority::UserRead);
        m_urgentRun = urgent && pollsWaiting ? m_urgentRun + 1 : 0;
        m_current = std::move(e);
        transmit();
        return;
    }
    armHoldTimer();
}

std::optional<RequestQueue::Entry> RequestQueue::takeSendable(std::deque<Entry> &q,
                                                              bool keepOrder) {
    for (auto it = q.begin(); it != q.end();) {
        if (!it->wanted()) {
            ++m_stats.skipped;
            it = q.erase(it);
        } else if (!isHeld(*it)) {
            Entry e = std::move(*it);
            q.erase(it);
            return e;
        } else if (keepOrder) {
            return std::nullopt; // a held write keeps the writes behind it waiting
        } else {
            ++it;
        }
    }
    return std::nullopt;
}

bool RequestQueue::isHeld(const Entry &e) const {
    return e.attempts == 0 && !e.matchAnything &&
           m_late.holds(e.frame.command, e.frame.target, nowMs());
}

void RequestQueue::hold(const QByteArray &command, std::optional<int> target, int requestBytes,
                        int minTurnaroundMs) {
    const int window =
        qMax(m_settings.lateAnswerWindowMs, answerBudgetMs(requestBytes, minTurnaroundMs));
    m_late.expect(command, target, nowMs() + window);
}

void RequestQueue::holdAfterTimeout(const Entry &e) {
    if (!e.matchAnything)
        hold(e.frame.command, e.frame.target,
             int(e.request.raw.isEmpty() ? e.frame.encode().size() : e.request.raw.size()),
             e.request.minTurnaroundMs);
}

void RequestQueue::holdForLateAnswer(std::optional<int> target, const QByteArray &command) {
    Frame read = Frame::read(command);
    if (target)
        read = read.addressed(m_settings.robotAddress, *target);
    hold(command, target, int(read.encode().size()));
}

void RequestQueue::armHoldTimer() {
    if (pendingCount() == 0)
        return;
    if (const auto deadline = m_late.nextDeadline(nowMs()))
        m_holdTimer.start(int(qMax<qint64>(0, *deadline - nowMs())));
}

} // namespace tipscope::link
