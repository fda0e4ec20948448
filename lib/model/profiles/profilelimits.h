// Profile limits: the rule that keeps a profile from leaving a device in a state its own limits
// forbid, shared by tipscope-cli and the GUI's profile dialog through ProfileApplier.
//
// The catalog's `limits` say which settings bound which: MIT <= MAT, and MIT <= STx <= MAT on
// every port. A profile is checked whole, before its first write, against the state the device
// would end in: the profile's values over the device's current ones. If a bound would break,
// within the profile (MAT 400 with ST1 450) or against the device (MAT 400 while the device's
// ST1 is 450, which the profile leaves alone or also sets to 450), or cannot be checked because
// a value involved is unknown, the profile is refused whole and nothing is written. Otherwise
// the writes are ordered so that every state in between keeps the limits too: the bounds that
// widen first (MAT up, MIT down), then the settings they bound, then the bounds that narrow.
// Only the catalog's limits count: alarm limits (HAx, LAx) and sleep temperatures are not bound
// by MIT and MAT in either guide, and a high alarm above MAT is how an overshoot is caught.
#pragma once

#include "profile.h"

#include <QSet>

namespace tipscope::model {

class DeviceModel;

// The codes whose current values the check needs: the profile's own, and every setting of the
// device that bounds, or is bounded by, one of them.
[[nodiscard]] QList<QByteArray> limitRelatedCodes(const Profile &profile,
                                                  const DeviceModel &device);

// One line per bound the state after `profile` would break or cannot prove, e.g.
// "ST1 450 °C (in the profile) is above MAT 400 °C (in the profile)"; empty when all hold.
// Uses the device's current values, so read limitRelatedCodes() first; `unread` are codes whose
// read failed, whose older value (from a poll, say) must not count as current.
[[nodiscard]] QStringList limitConflicts(const Profile &profile, const DeviceModel &device,
                                         const QSet<QByteArray> &unread = {});

// `codes` (settings of `profile` to write) in an order that keeps every limit after each write,
// for a profile without limitConflicts().
[[nodiscard]] QList<QByteArray> limitSafeOrder(const QList<QByteArray> &codes,
                                               const Profile &profile, const DeviceModel &device);

} // namespace tipscope::model
