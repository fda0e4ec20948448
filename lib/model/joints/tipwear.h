// TipWear: notices a tip that recovers more slowly than it did when it was plugged in (a worn or
// oxidised tip draws heat back more slowly).
//
// Per device and port: the first kWindow recovered joints after a tool was plugged in are that
// tip's baseline (their median recovery time). From then on the median of its last kWindow
// recoveries is compared with the baseline; when it is more than `share` slower (0.3: 30 %), a
// notice is given, once, until the tool changes (toolChanged(), or a joint made with another
// tool). Joints that never recovered or were not judged do not count. Plain computation.
#pragma once

#include "model/joints/jointrecord.h"

#include <QHash>
#include <deque>

namespace tipscope::model {

class TipWear {
public:
    static constexpr int kWindow = 10;

    struct Notice {
        DeviceIdentity device;
        int port = 0;
        QString tool;
        qint64 baselineMs = 0; // median recovery of the first joints
        qint64 recentMs = 0;   // median recovery of the last joints
    };

    [[nodiscard]] std::optional<Notice> add(const JointRecord &joint, double share);
    void toolChanged(const DeviceIdentity &device, int port);
    // The baseline of a port's tip, once its first kWindow joints are in.
    [[nodiscard]] std::optional<qint64> baselineMs(const DeviceIdentity &device, int port) const;
    // The median of its last (up to kWindow) recoveries after the baseline's: what the baseline
    // is compared with. Empty until one came.
    [[nodiscard]] std::optional<qint64> recentMs(const DeviceIdentity &device, int port) const;
    // "tip wearing: C245 recovers in 2.6 s (median of the last 10 joints), 1.8 s when new"
    [[nodiscard]] static QString noticeText(const Notice &notice);

private:
    struct Tip {
        QString tool;
        std::vector<qint64> first;
        std::deque<qint64> recent;
        bool noticed = false;
    };

    QHash<QString, Tip> m_tips; // by device key and port
};

} // namespace tipscope::model
Q_DECLARE_METATYPE(tipscope::model::TipWear::Notice)
