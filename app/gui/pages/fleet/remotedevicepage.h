// RemoteDevicePage: a device another TipScope publishes to the plant's broker, read-only: who it
// is and where, whether its agent is online and its line up, each port's live values, the errors
// and alarms in force, and its recent joints, newest first. It follows what the PlantWatch keeps
// of the device, at most a few times a second; nothing here can be sent to the device.
#pragma once

#include <QTimer>
#include <QWidget>

class QLabel;
class QTableWidget;

namespace tipscope::plant {
class PlantWatch;
}

namespace tipscope::gui {

class RemoteDevicePage : public QWidget {
    Q_OBJECT
public:
    // `watch` must outlive the page.
    RemoteDevicePage(const plant::PlantWatch &watch, QWidget *parent = nullptr);

    void showDevice(const QString &root);
    [[nodiscard]] QString root() const { return m_root; }
    // What the page shows, as text, for tests: the header, then each table row.
    [[nodiscard]] QStringList lines() const;

Q_SIGNALS:
    // The button back to the fleet overview, where the tile was.
    void backRequested();

private:
    void refresh();

    const plant::PlantWatch &m_watch;
    QString m_root;
    QLabel *m_title;
    QLabel *m_state;
    QTableWidget *m_ports;
    QLabel *m_alarms;
    QTableWidget *m_joints;
    QTimer m_refresh;
};

} // namespace tipscope::gui
