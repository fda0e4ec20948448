// Where a file dialog opens: the Documents folder when the account has one, else the home folder.
// A fresh account often has no Documents folder yet, and a dialog offered a folder that does not
// exist opens somewhere else than it says (or on the working folder), with a path to nowhere.
#pragma once

#include <QString>

namespace tipscope::gui {

[[nodiscard]] QString startFolder();

} // namespace tipscope::gui
