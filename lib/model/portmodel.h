// PortModel: one tool port of a station, as a view onto the station's parameters of that port
// (TTx, STx, PPx, PSx, ...) plus what people ask of a port: the decoded status flags, the tool,
// the error in words, the per-tool settings of every tool the family supports (connected tool
// first), and the robot's own controls (working / stand / cooling, selected temperature).
#pragma once

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

class PortModel : public QObject {
    Q_OBJECT
public:
    PortModel(StationModel &station, int port, QObject *parent = nullptr);

    [[nodiscard]] int number() const { return m_port; }
    [[nodiscard]] StationModel &station() const { return m_station; }
    // The parameter of this port with the given two-letter base ("TT" -> TT1 on port 1).
    [[nodiscard]] Parameter *param(const char *base) const;

    [[nodiscard]] std::optional<qint64> tipTemperature() const;
    [[nodiscard]] std::optional<qint64> selectedTemperature() const;
    [[nodiscard]] std::optional<qint64> power() const; // per mille
    [[nodiscard]] std::optional<PortStatus> status() const;
    [[nodiscard]] std::optional<int> tool() const;
    [[nodiscard]] QString toolName() const;
    [[nodiscard]] std::optional<int> error() const;
    [[nodiscard]] QString errorText() const;
    [[nodiscard]] int alarmFlags() const;

    [[nodiscard]] QList<int> toolOrder() const;
    [[nodiscard]] QList<Parameter *> toolSettings(int tool) const; // adjust, sleep temp, delays
    [[nodiscard]] QList<Parameter *> alarmSettings() const;
    [[nodiscard]] QList<Parameter *> counters() const;
    [[nodiscard]] QList<Parameter *> liveParameters() const; // TT, PP, PS
    [[nodiscard]] QList<Parameter *> statusParameters() const;

    // The robot's controls; each returns an error (nothing sent) or empty when the write started.
    QString setMode(int writeValue); // 0 working, 1 stand, 10 cooling (as the family allows)
    QString setSelectedTemperature(qint64 celsius);

Q_SIGNALS:
    void changed();

private:
    StationModel &m_station;
    int m_port;
};

} // namespace tipscope::model
