// Page: one page of the main window's page area (overview, settings, counters, errors,
// feeder, console, ...). Pages only talk to the models of the Session; they never build frames.
//
// The main window calls setSelection() when the device tree selection changes (a device, and a
// port when one is selected; nullptr when nothing is) and setActive() when the page is shown or
// hidden, so a page can ask the poll scheduler for what it shows (visiblePorts()) and refresh
// its settings when it opens.
#pragma once

#include "model/session.h"

#include <QPointer>
#include <QWidget>

namespace tipscope::gui {

class Page : public QWidget {
    Q_OBJECT
public:
    Page(model::Session &session, QWidget *parent = nullptr)
        : QWidget(parent)
        , m_session(session) {}

    [[nodiscard]] virtual QString title() const = 0;
    // Whether the page has anything to show for this device (the feeder page only for feeders).
    [[nodiscard]] virtual bool appliesTo(const model::DeviceModel *device) const {
        Q_UNUSED(device);
        return true;
    }
    virtual void setSelection(model::DeviceModel *device, int port) {
        m_device = device;
        m_port = port;
    }
    virtual void setActive(bool active) { m_active = active; }
    // Ports of the selected station whose live values this page shows.
    [[nodiscard]] virtual QSet<int> visiblePorts() const { return {}; }

protected:
    model::Session &m_session;
    QPointer<model::DeviceModel> m_device;
    int m_port = 0;
    bool m_active = false;
};

} // namespace tipscope::gui
