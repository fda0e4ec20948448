// RemoteDevicePage: a device another TipScope publishes to the plant's broker, read-only: who it
// is and where, whether its agent is online and its line up, each port's live values, their curves
// over the last minutes (from the live topic, kept since this window began watching), the errors
// and alarms in force, and its recent joints, newest first. It follows what the PlantWatch keeps
// of the device, at most a few times a second; nothing here can be sent to the device.
#pragma once

#include <QTimer>
#include <QWidget>

class QLabel;
class QTableWidget;

namespace tipscope::plant {
class PlantWatch;
class RemoteHistory;
} // namespace tipscope::plant

namespace tipscope::gui {

class ChartWidget;

class RemoteDevicePage : public QWidget {
    Q_OBJECT
public:
    // `watch` must outlive the page.
    RemoteDevicePage(const plant::PlantWatch &watch, QWidget *parent = nullptr);

    void showDevice(const QString &root);
    [[nodiscard]] QString root() const { return m_root; }
    // What the page shows, as text, for tests: the header, then each table row.
    [[nodiscard]] QStringList lines() const;
    [[nodiscard]] const plant::RemoteHistory &history() const { return *m_history; }
    [[nodiscard]] const ChartWidget &chart() const { return *m_chart; }
    // How far back the chart looks.
    static constexpr qint64 kChartSpanMs = 10 * 60 * 1000;

Q_SIGNALS:
    // The button back to the fleet overview, where the tile was.
    void backRequested();

private:
    void refresh();
    void drawChart();

    const plant::PlantWatch &m_watch;
    QString m_root;
    QLabel *m_title;
    QLabel *m_state;
    QTableWidget *m_ports;
    plant::RemoteHistory *m_history;
    ChartWidget *m_chart;
    QString m_chartChannels; // the keys the chart's series were set for
    QLabel *m_alarms;
    QTableWidget *m_joints;
    QTimer m_refresh;
};

} // namespace tipscope::gui
