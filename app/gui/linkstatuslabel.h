// LinkStatusLabel: the status bar's line statistics (transactions per second, median latency,
// timeouts, BCC errors, NAKs), refreshed twice a second, with the full breakdown as tooltip.
#pragma once

#include "model/session.h"

#include <QLabel>
#include <QTimer>

namespace tipscope::gui {

class LinkStatusLabel : public QLabel {
    Q_OBJECT
public:
    explicit LinkStatusLabel(model::Session &session, QWidget *parent = nullptr);
    void refresh();

private:
    model::Session &m_session;
    QTimer m_timer;
};

} // namespace tipscope::gui
