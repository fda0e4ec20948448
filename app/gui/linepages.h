// LinePages: the pages of one line (overview, settings, ..., charts, joints) as tabs, showing the
// device selected on that line. The main window has one for the connection bar's line and one for
// each line of the open workspace, so every page works for any device as it does for one line.
//
// On the connection bar's line, only the LinePages on screen asks its session's poll scheduler for
// live values (the ports its current page shows); hidden, it asks for none, and the wire goes to
// what is seen. A workspace line polls every port live whatever is shown (Workspace), for its
// joints and the fleet overview; its pages leave that alone (PortsPolled::Every).
#pragma once

#include "model/session.h"

#include <QTabWidget>

namespace tipscope::gui {

class Page;

class LinePages : public QTabWidget {
    Q_OBJECT
public:
    enum class PortsPolled { Shown, Every };

    // The Joints page reads the journal at `journalPath`.
    LinePages(model::Session &session, const QString &journalPath, PortsPolled polled,
              QWidget *parent = nullptr);

    [[nodiscard]] model::Session &session() const { return m_session; }
    [[nodiscard]] Page *page(const QString &title) const;
    [[nodiscard]] const QList<Page *> &pageList() const { return m_pages; }
    [[nodiscard]] model::DeviceModel *selectedDevice() const { return m_device; }

    void select(model::DeviceModel *device, int port);
    // Whether these are the pages on screen.
    void setShown(bool shown);
    // Live joints are stamped with it until the journal has them.
    void setWorkOrder(const QString &workOrder);
    // Brings the page of this title to the front, when the selected device has it.
    void showPage(const QString &title);

private:
    void onTabChanged(int index);
    void updateVisiblePorts();

    model::Session &m_session;
    QList<Page *> m_pages;
    model::DeviceModel *m_device = nullptr;
    PortsPolled m_polled;
    bool m_shown = false;
};

} // namespace tipscope::gui
