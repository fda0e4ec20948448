// The pages of the main window, in tab order.
#pragma once

#include "page.h"

namespace tipscope::gui {

[[nodiscard]] QList<Page *> createPages(model::Session &session, QWidget *parent);

} // namespace tipscope::gui
