// A real X server of the test's own (Xvfb on a display number it picks itself), so that a widget
// test runs on Qt's xcb platform as a person's desktop does: window manager hints, real font
// rendering, real input events and repaint timing, which the offscreen platform leaves out.
//
// Start it before the QApplication exists (from the test class's static initMain()): it points
// DISPLAY at the new server and QT_QPA_PLATFORM at xcb. It stops when the program ends, after
// the QApplication has closed its connection (a server gone first makes Qt's xcb plugin abort).
#pragma once

#include <QSize>
#include <QString>

namespace tipscope::testing {

// Starts Xvfb with one screen of `screen` pixels and makes it this process's display. Empty on
// success, else why not (no Xvfb installed, or it did not come up within a few seconds).
[[nodiscard]] QString startXvfbDisplay(QSize screen);

} // namespace tipscope::testing
