// fileNamePart(): a piece of a file name made from a name people chose (a workspace line's), so
// that the file stays in the folder it is meant for whatever the name holds.
//
// A separator ('/' or '\'), a control character or a character that is not a valid Unicode
// character becomes '_'; a part made only of dots ("..") has each dot replaced too, so it can
// never name the folder above; an empty name gives "_". The part is cut to kFileNamePartChars
// characters, so that with a prefix and an extension it stays below the 255 bytes a file name
// may have. Different names may give the same part: callers that make several files check that
// their paths differ.
#pragma once

#include <QString>

namespace tipscope::base::io {

inline constexpr int kFileNamePartChars = 48;

[[nodiscard]] QString fileNamePart(const QString &name);

} // namespace tipscope::base::io
