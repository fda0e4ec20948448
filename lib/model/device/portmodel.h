// PortModel: one tool port of a station, as a view onto the station's parameters of that port
// (found by their catalog role: tip temperature, setpoint, power, status, ...) plus what people
// ask of a port: the decoded status flags and alarm, the tool, the error in words and its level,
// the per-tool settings of every tool the family supports (connected tool first), and the
// robot's own controls (working / stand / cooling, selected temperature).
#pragma once

#include "model/events/problemlevel.h"
#include "parameter.h"

#include <QObject>

namespace tipscope::model {

class StationModel;

// R-PSx is one number whose digits are separate facts; see docs/protocol-notes.md.
struct PortStatus {
    enum class Mode { Working = 0, Stand = 1, Sleep = 2, Hibernation = 3 };
    Mode mode = Mode::Working;
    bool cooling = false;
    bool suction = false;
    int motor = 0; // 0 off, 1 forward, 2 backward

    [[nodiscard]] static PortStatus fromNumber(qint64 value);
    [[nodiscard]] QString text() const;
    [[nodiscard]] static QString modeName(Mode mode);
    friend bool operator==(const PortStatus &a, const PortStatus &b) {
        return a.mode == b.mode && a.cooling == b.cooling && a.suction == b.suction &&
               a.motor == b.motor;
    }
};

// R-TAx: the units digit is the high temperature alarm, the tens digit the low one (the robot
// stations clear both when they are read).
struct TemperatureAlarm {
    bool high = false;
    bool low = false;

    [[nodiscard]] static TemperatureAlarm fromNumber(qint64 value);
    [[nodiscard]] bool any() const { return high || low; }
    // "High temperature, Low temperature", or "None".
    [[nodiscard]] QString text() const;
    // What to check for the alarm, in words, as the error tables have; empty without an alarm.
    [[nodiscard]] QString advice() const;
    [[nodiscard]] Level level() const { return any() ? Level::Warning : Level::Ok; }
    friend bool operator==(const TemperatureAlarm &a, const TemperatureAlarm &b) {
        return a.high == b.high && a.low == b.low;
    }
};

class PortModel : public QObject {
    Q_OBJECT
public:
    PortModel(StationModel &station, int port, QObject *parent = nullptr);

    [[nodiscard]] int number() const { return m_port; }
    [[nodiscard]] StationModel &station() const { return m_station; }
    // The value of this port with the given role, or null when the family has none.
    [[nodiscard]] Parameter *parameter(protocol::Role role) const;
    // The value's text as people read it; "—" before the first reading or when there is none.
    [[nodiscard]] QString displayText(protocol::Role role) const;
    // The values of this port with these roles that the family has, in the order asked.
    [[nodiscard]] QList<Parameter *> parameters(std::initializer_list<protocol::Role> roles) const;

    [[nodiscard]] std::optional<qint64> tipTemperature() const;
    [[nodiscard]] std::optional<qint64> selectedTemperature() const;
    [[nodiscard]] std::optional<qint64> power() const; // per mille
    [[nodiscard]] std::optional<PortStatus> status() const;
    [[nodiscard]] std::optional<int> tool() const;
    [[nodiscard]] QString toolName() const;
    [[nodiscard]] QString toolName(int tool) const; // from the family's tool table
    [[nodiscard]] std::optional<int> error() const;
    [[nodiscard]] QString errorText() const;
    [[nodiscard]] Level errorLevel() const; // Unknown until read
    [[nodiscard]] std::optional<TemperatureAlarm> alarm() const;
    [[nodiscard]] int alarmFlags() const; // R-TAx as read, 0 before

    [[nodiscard]] QList<int> toolOrder() const;
    // The catalog's groups on this port, in catalog order.
    [[nodiscard]] QList<Parameter *> settings() const;             // "port": the setpoint
    [[nodiscard]] QList<Parameter *> toolSettings(int tool) const; // "tool" of that tool
    [[nodiscard]] QList<Parameter *> alarmSettings() const;        // "alarm"
    [[nodiscard]] QList<Parameter *> counters() const;             // "counter"
    [[nodiscard]] QList<Parameter *> liveParameters() const;       // tip, power, status, setpoint
    [[nodiscard]] QList<Parameter *> statusParameters() const;

    // The robot's controls; each returns an error (nothing sent) or empty when the write started.
    QString setMode(int writeValue); // 0 working, 1 stand, 10 cooling (as the family allows)
    QString setSelectedTemperature(qint64 celsius);

Q_SIGNALS:
    void changed();

private:
    QString write(protocol::Role role, qint64 value);

    StationModel &m_station;
    int m_port;
};

} // namespace tipscope::model
