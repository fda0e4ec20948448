// Atomic saves: every file TipScope writes in one go is replaced whole or not at all.
//
// saveAtomically() writes through QSaveFile: the old file stays as it was until the new one is
// complete on disk, so a full disk, a pulled USB stick or a crash never leaves half a file where
// a good one was. A failure says "cannot write <path>: <reason>" in the user's language, the
// path elided the way every echoed input is. Files written as they grow (recordings, the CLI's
// monitor CSV) are not saves and do not come here.
#pragma once

#include "base/outcome.h"

#include <QByteArray>
#include <QIODevice>
#include <QString>
#include <functional>

namespace tipscope::base::io {

[[nodiscard]] base::Outcome<void> saveAtomically(const QString &path, const QByteArray &bytes);
// The same for a file too big to build in memory first (a day of a chart as CSV): `write` fills
// the device and returns false when writing failed.
[[nodiscard]] base::Outcome<void> saveAtomically(const QString &path,
                                                 const std::function<bool(QIODevice &)> &write);

} // namespace tipscope::base::io
