// Echoing input in messages: what a person typed, or a file held, quoted in an error message so
// that the message stays readable whatever the input was.
//
// elided() shows up to `maxChars` characters whole. A longer text is cut to its first
// `maxChars` characters, followed by "…" and its full length: a 100 kB argument becomes
// "SSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSS… (102400 characters)". Control characters are shown
// by their code ("<1B>"), so an argument cannot move the cursor or clear a terminal. Every
// message that echoes user input (options, codes, values, file names, profile keys) goes through
// this one function; file names get kElidePathChars, since their end is what tells them apart.
#pragma once

#include <QString>

namespace tipscope::base {

inline constexpr int kElideChars = 40;
inline constexpr int kElidePathChars = 160;

[[nodiscard]] QString elided(const QString &text, int maxChars = kElideChars);
[[nodiscard]] inline QString elidedPath(const QString &path) {
    return elided(path, kElidePathChars);
}

} // namespace tipscope::base
