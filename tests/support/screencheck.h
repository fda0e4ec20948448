// What a person sees of a window, checked as they would see it: a text cut short ("Port 1 (T2",
// "Tempera…"), two widgets laid over each other, a page that needs a horizontal scroll bar at the
// size it is shown. ElidedLabel is the one text allowed to be cut: it is made to cut long status
// text with "…" and carries the whole text as its tooltip.
#pragma once

#include <QString>
#include <QStringList>

class QWidget;

namespace tipscope::testing {

// Plain text as drawn: no mnemonic ampersand, no rich-text tags.
[[nodiscard]] QString shownText(QString text);
// Class and object name, to say which widget a problem is in.
[[nodiscard]] QString widgetName(const QWidget *w);
// Why `w`'s text does not fit, or empty when it does (or `w` is not a text widget).
[[nodiscard]] QString clippedText(QWidget *w);
// Every such problem among the widgets of `top` a person can see now, one line each.
[[nodiscard]] QStringList screenProblems(QWidget &top);

} // namespace tipscope::testing
