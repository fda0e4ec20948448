#include "model/joints/tipwear.h"

#include "base/timetext.h"

#include <QCoreApplication>
#include <QLocale>
#include <algorithm>

namespace tipscope::model {

namespace {
struct TipWearTr {
    Q_DECLARE_TR_FUNCTIONS(TipWear)
};

QString tipKey(const DeviceIdentity &device, int port) {
    return device.key() + QLatin1Char('#') + QString::number(port);
}

template <typename Values> qint64 median(const Values &values) {
    std::vector<qint64> sorted(values.begin(), values.end());
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    return n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}
} // namespace

std::optional<TipWear::Notice> TipWear::add(const JointRecord &joint, double share) {
    if (!joint.recoveryMs || joint.verdict == JointVerdict::Incomplete)
        return std::nullopt;
    Tip &tip = m_tips[tipKey(joint.device, joint.port)];
    if (tip.tool != joint.tool)
        tip = Tip{joint.tool, {}, {}, false};
    if (int(tip.first.size()) < kWindow) {
        tip.first.push_back(*joint.recoveryMs);
        return std::nullopt;
    }
    tip.recent.push_back(*joint.recoveryMs);
    if (int(tip.recent.size()) > kWindow)
        tip.recent.pop_front();
    if (tip.noticed || int(tip.recent.size()) < kWindow)
        return std::nullopt;
    const qint64 baseline = median(tip.first);
    const qint64 recent = median(tip.recent);
    if (double(recent) <= double(baseline) * (1 + share))
        return std::nullopt;
    tip.noticed = true;
    return Notice{joint.device, joint.port, joint.tool, baseline, recent};
}

void TipWear::toolChanged(const DeviceIdentity &device, int port) {
    m_tips.remove(tipKey(device, port));
}

std::optional<qint64> TipWear::baselineMs(const DeviceIdentity &device, int port) const {
    const auto it = m_tips.constFind(tipKey(device, port));
    if (it == m_tips.cend() || int(it->first.size()) < kWindow)
        return std::nullopt;
    return median(it->first);
}

std::optional<qint64> TipWear::recentMs(const DeviceIdentity &device, int port) const {
    const auto it = m_tips.constFind(tipKey(device, port));
    if (it == m_tips.cend() || it->recent.empty())
        return std::nullopt;
    return median(it->recent);
}

QString TipWear::noticeText(const Notice &notice) {
    return TipWearTr::tr(
               "tip wearing: %1 recovers in %2 s (median of the last %3 joints), %4 s when "
               "it was plugged in")
        .arg(notice.tool.isEmpty() ? TipWearTr::tr("the tool") : notice.tool,
             base::secondsText(notice.recentMs))
        .arg(kWindow)
        .arg(base::secondsText(notice.baselineMs));
}

} // namespace tipscope::model
