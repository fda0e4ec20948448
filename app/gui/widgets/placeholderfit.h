// A text field wide enough for the examples it shows while empty ("e.g. ST1", "none for reads"):
// a field sized for the English example cut the German and Spanish ones short, and a cut
// example says nothing about what to type.
#pragma once

#include <QStringList>

class QLineEdit;

namespace tipscope::gui {

// Makes `edit` at least wide enough for the longest of `examples` (as its placeholder), with
// its frame, margins and clear button; a maximum width below that is raised to it.
void fitPlaceholders(QLineEdit &edit, const QStringList &examples);

} // namespace tipscope::gui
