// Reading a broker password from where it may live: a file (readable by the service's user
// only) or an environment variable. Never from a command-line argument, which `ps` shows to
// every user. The value is returned as bytes, with one trailing line break removed; errors name
// the file or the variable, never the value, in the user's language.
#pragma once

#include "base/outcome.h"

#include <QByteArray>
#include <QString>

namespace tipscope::mqtt {

// The first line of the file at `path`. Refuses a missing, unreadable, empty or oversized
// (over 4 KiB) file.
[[nodiscard]] base::Outcome<QByteArray> readSecretFile(const QString &path);

// The value of the environment variable `name`. Refuses an unset or empty variable.
[[nodiscard]] base::Outcome<QByteArray> readSecretEnvironment(const QString &name);

} // namespace tipscope::mqtt
