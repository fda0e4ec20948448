// FleetTile: what the fleet overview shows of one device of a workspace line, as plain values any
// front end can draw: the names people give the device and its line, the model, each port's tip
// temperature against its setpoint with power, status and tool, the errors and alarms with their
// Level, the last joint's verdict, and whether the line is up or since when it is down.
//
// A FleetTile follows one device of one line of a Workspace; it owns nothing and the device may
// go (its models are the Session's): state() then describes nothing new. changed() says that
// something state() reports may differ (a value, the line going up or down, a joint); it comes
// for every change, so a view coalesces it. sampleArrived() comes for every tip-temperature
// reading, changed or not, so a view can measure how late it shows a sample. The time the line
// went down is taken from the injected clock when the tile sees it happen; a tile made while
// the line is already down takes the device's last reading instead (the line was up then).
#pragma once

#include "model/device/devicemodel.h"
#include "model/events/problemlevel.h"
#include "model/joints/jointrecord.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>

namespace tipscope::model {

class Workspace;

struct FleetPortState {
    int number = 0;
    std::optional<qint64> tip;      // °C as read
    std::optional<qint64> setpoint; // °C as read
    QString tipText;                // in the display unit; "—" before the first reading
    QString setpointText;
    QString powerText;
    QString toolText;
    QString statusText;
    std::optional<JointVerdict> lastJoint;

    friend bool operator==(const FleetPortState &a, const FleetPortState &b);
    friend bool operator!=(const FleetPortState &a, const FleetPortState &b) { return !(a == b); }
};

struct FleetProblem {
    Level level = Level::Unknown;
    QString text; // "Port 1: Tip not detected", "Port 2 alarm: High temperature"

    friend bool operator==(const FleetProblem &a, const FleetProblem &b) {
        return a.level == b.level && a.text == b.text;
    }
};

struct FleetTileState {
    QString deviceName; // Workspace::deviceName()
    QString lineName;
    QString cell;
    QString model;
    QList<FleetPortState> ports;           // a station's; none for a feeder
    QString feederText;                    // a feeder's feeding state and fed length
    QList<FleetProblem> problems;          // worst first
    std::optional<JointVerdict> lastJoint; // the device's latest, whichever port
    int lastJointPort = 0;
    bool read = false; // any of its values has been read
    bool lineUp = false;
    std::optional<qint64> downSinceMs; // while down, when known (ms since the epoch)
    QString lineText;                  // empty while up: "Line down since 08:12"
    bool lineOnly = false;             // the tile of a line without a device (LineTile)

    // The worst of the problems and the last joint (jointLevel()); Ok when there is none, Unknown
    // before anything was read and no problem is known.
    [[nodiscard]] Level worst() const;
    // The line is down, or a problem or the last joint is a Warning or worse.
    [[nodiscard]] bool needsAttention() const;
    // 0 is the worst: the line down (nothing is known), then Error, Warning, Info, Ok, not read.
    [[nodiscard]] int stateRank() const;

    friend bool operator==(const FleetTileState &a, const FleetTileState &b);
    friend bool operator!=(const FleetTileState &a, const FleetTileState &b) { return !(a == b); }
};

enum class FleetSortKey { Name, Line, State };
// Whether `a` goes before `b`: by device name, by line (then name), or by state (worst first,
// then name). Names compare as people count ("cell-2" before "cell-10").
[[nodiscard]] bool fleetTileBefore(const FleetTileState &a, const FleetTileState &b,
                                   FleetSortKey key);

// What a fleet overview draws a tile from: a device of this window's workspace (FleetTile), or
// one another TipScope publishes to the plant's broker (plant::RemoteTile). changed() says that
// state() may differ; sampleArrived() comes for every tip reading, changed or not.
class FleetTileSource : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    [[nodiscard]] virtual FleetTileState state() const = 0;
    // The workspace line and the device of a local tile; -1 and null for a remote one.
    [[nodiscard]] virtual int lineIndex() const { return -1; }
    [[nodiscard]] virtual DeviceModel *device() const { return nullptr; }

Q_SIGNALS:
    void changed();
    void sampleArrived();
};

class FleetTile : public FleetTileSource {
    Q_OBJECT
public:
    using Clock = std::function<qint64()>; // milliseconds since the epoch

    // `clock`: none is the system's.
    FleetTile(const Workspace &workspace, int line, DeviceModel &device, Clock clock = {},
              QObject *parent = nullptr);

    [[nodiscard]] int lineIndex() const override { return m_line; }
    [[nodiscard]] DeviceModel *device() const override { return m_device; }
    [[nodiscard]] FleetTileState state() const override;
    // "Line down since 08:12" (with the date when not today by the clock), "Line down".
    [[nodiscard]] static QString downText(std::optional<qint64> sinceMs, qint64 nowMs);

private:
    void onLineUpChanged(bool up);
    void onJoint(const JointRecord &joint);
    [[nodiscard]] std::optional<qint64> lastReadingMs() const;

    const Workspace &m_workspace;
    int m_line;
    QPointer<DeviceModel> m_device;
    Clock m_clock;
    std::optional<qint64> m_downSinceMs;
    QMap<int, JointVerdict> m_portJoints;
    std::optional<JointVerdict> m_lastJoint;
    int m_lastJointPort = 0;
};

} // namespace tipscope::model
