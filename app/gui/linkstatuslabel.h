// LinkStatusLabel: the status bar's line statistics (transactions per second, median latency,
// timeouts, BCC errors, NAKs), refreshed twice a second, with the full breakdown as tooltip. It
// follows the line whose pages are shown (setSession()); with none (the fleet overview), hidden.
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
    // The line to follow; the session must outlive it or be replaced first.
    void setSession(model::Session *session);

private:
    model::Session *m_session;
    QTimer m_timer;
};

} // namespace tipscope::gui
