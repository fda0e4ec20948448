#include "lateanswers.h"

#include <algorithm>

namespace tipscope::link {

using protocol::Frame;
using protocol::Header;

void LateAnswers::expect(const QByteArray &command, std::optional<int> device, qint64 untilMs) {
    for (Hold &h : m_holds) {
        if (h.command == command && h.device == device) {
            h.untilMs = std::max(h.untilMs, untilMs);
            ++h.expected;
            return;
        }
    }
    m_holds.push_back({command, device, untilMs, 1});
}

bool LateAnswers::holds(const QByteArray &command, std::optional<int> device, qint64 nowMs) const {
    return std::any_of(m_holds.begin(), m_holds.end(), [&](const Hold &h) {
        return h.untilMs > nowMs && h.command == command && h.device == device;
    });
}

bool LateAnswers::absorb(const Frame &stray, int robotAddress) {
    if (stray.header != Header::Answer && stray.header != Header::Nak)
        return false;
    if (stray.isAddressed() && stray.target != robotAddress)
        return false;
    const auto it = std::find_if(m_holds.begin(), m_holds.end(), [&](const Hold &h) {
        if (h.command != stray.command)
            return false;
        return stray.isAddressed() ? h.device == stray.source : !h.device.has_value();
    });
    if (it == m_holds.end())
        return false;
    if (--it->expected <= 0)
        m_holds.erase(it);
    return true;
}

std::optional<qint64> LateAnswers::nextDeadline(qint64 nowMs) {
    m_holds.erase(std::remove_if(m_holds.begin(), m_holds.end(),
                                 [nowMs](const Hold &h) { return h.untilMs <= nowMs; }),
                  m_holds.end());
    std::optional<qint64> next;
    for (const Hold &h : m_holds)
        next = std::min(next.value_or(h.untilMs), h.untilMs);
    return next;
}

} // namespace tipscope::link
