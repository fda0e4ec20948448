// Screenshots of every page in demo mode, for the documentation (scripts/screenshots).
#pragma once

#include <QString>

namespace tipscope::gui {

class MainWindow;

// After the demo has run a while, grabs the window on each page into `folder` and quits.
void takeScreenshots(MainWindow &window, const QString &folder);

} // namespace tipscope::gui
