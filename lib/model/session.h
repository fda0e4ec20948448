// Session: everything TipScope does with one line, for the application and its tests.
//
// connectTo() builds the line (serial, TCP, or the built-in simulated DME + SFR of demo mode),
// opens it, finds the devices (or identifies the one the settings name), and builds a
// StationModel or FeederModel for each, registered with the poll scheduler, the event log and
// the telemetry recorder. A line that is lost keeps its device models: the line reconnects by
// itself and polling resumes; each device model is told whether the line is up. Monitor-only and
// the temperature unit apply to every device. The device models describe their devices from the
// built-in catalog unless the session is given another (tests add entries); it must outlive the
// session.
#pragma once

#include "model/device/feedermodel.h"
#include "model/device/stationmodel.h"
#include "model/events/eventlog.h"
#include "model/joints/jointwatcher.h"
#include "model/live/pollscheduler.h"
#include "model/live/sessionclock.h"
#include "model/live/telemetryrecorder.h"
#include "model/telemetry/telemetry.h"

#include "link/discovery.h"
#include "link/line.h"

#include <QObject>
#include <memory>

namespace tipscope::sim {
class SimLine;
}

namespace tipscope::model {

class Session : public QObject {
    Q_OBJECT
public:
    enum class Addressing { Auto, With, Without };
    enum class State { Disconnected, Connecting, Detecting, Connected, Retrying, Failed };
    Q_ENUM(State)

    struct Settings {
        link::LineSettings line;
        Addressing addressing = Addressing::Auto;
        int targetAddress = 1;
        bool scanAllAddresses = false;
        // On the demo line: its station's ports solder and rest, its feeder feeds.
        bool demoActivity = false;
        // The demo line answers as a real station on a 19200-baud wire through a USB adapter
        // would; off, it answers at once (tests that do not measure the wire).
        bool demoPaced = true;
        // A chart recording played as the line's samples instead of a wire (RecordingPlayback,
        // which a workspace starts for such a line): no devices, nothing polled; the recorded
        // tip curves reach the joint watcher and the journal as a wire's would.
        QString recordingPath;
    };

    explicit Session(QObject *parent = nullptr);
    explicit Session(const protocol::Catalog &catalog, QObject *parent = nullptr);
    ~Session() override;

    void connectTo(const Settings &settings);
    void disconnectFromLine();
    // A line played from a recording (Settings::recordingPath): the playback says how it goes
    // (Connected while it plays, Disconnected once played, Failed when the file is refused).
    [[nodiscard]] bool isPlayback() const { return !m_settings.recordingPath.isEmpty(); }
    // The line as the identities of a playback's devices name it: "recording <absolute path>".
    [[nodiscard]] QString playbackLine() const;
    void setPlaybackState(State state, const QString &text);

    [[nodiscard]] State state() const { return m_state; }
    [[nodiscard]] QString stateText() const { return m_stateText; }
    [[nodiscard]] const Settings &settings() const { return m_settings; }
    [[nodiscard]] const QList<DeviceModel *> &devices() const { return m_devices; }
    [[nodiscard]] StationModel *station() const;
    [[nodiscard]] FeederModel *feeder() const;
    [[nodiscard]] link::Line *line() const { return m_line.get(); }
    [[nodiscard]] sim::SimLine *demoLine() const { return m_demo.get(); }
    [[nodiscard]] PollScheduler &scheduler() { return m_scheduler; }
    [[nodiscard]] EventLog &eventLog() { return m_log; }
    [[nodiscard]] Telemetry &telemetry() { return m_telemetry; }
    // The joints of every station's ports, found live; one outside its limits, and a tip that
    // wears, is also a warning in the event log (kind Joint).
    [[nodiscard]] JointWatcher &joints() { return m_joints; }

    [[nodiscard]] TemperatureUnit temperatureUnit() const { return m_unit; }
    void setTemperatureUnit(TemperatureUnit unit);
    [[nodiscard]] bool monitorOnly() const { return m_monitorOnly; }
    void setMonitorOnly(bool on);

Q_SIGNALS:
    void stateChanged(tipscope::model::Session::State state, const QString &text);
    void devicesChanged();
    void monitorOnlyChanged(bool on);
    void temperatureUnitChanged();

private:
    void setState(State s, const QString &text);
    void onLineState(link::Line::State s, const QString &detail);
    void detect();
    // `unidentified`: why the device the settings name was not identified, when it was not.
    void adoptDevices(const QList<link::DeviceInfo> &found, const QString &unidentified = {});
    void identify(std::optional<int> address);
    void clearDevices();
    void warnOfJoint(const JointRecord &joint);
    void noticeWear(const TipWear::Notice &notice);
    void logJointWarning(const DeviceIdentity &device, int port, const QString &text);
    [[nodiscard]] QString connectedText() const;
    [[nodiscard]] qint64 sampleTimeMs() const;

    const protocol::Catalog &m_catalog;
    Settings m_settings;
    std::unique_ptr<sim::SimLine> m_demo;
    std::unique_ptr<link::Line> m_line;
    std::unique_ptr<link::Discovery> m_discovery;
    QList<DeviceModel *> m_devices;
    PollScheduler m_scheduler;
    EventLog m_log;
    Telemetry m_telemetry;
    TelemetryRecorder m_recorder;
    JointWatcher m_joints;
    State m_state = State::Disconnected;
    QString m_stateText;
    TemperatureUnit m_unit = TemperatureUnit::Celsius;
    bool m_monitorOnly = false;
    // Stamps samples and events alike; mutable as it catches up after a sleep when read.
    mutable SessionClock m_clock;
};

} // namespace tipscope::model
