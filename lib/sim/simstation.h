// SimStation: a simulated soldering station of any family (UCR ... HDR).
//
// Each port carries a tool and a first-order thermal model: the controller asks for power to
// reach the target (selected temperature plus the tool's adjust when working, the tool's sleep
// temperature in sleep, off in hibernation, cooling or with no tool), limited by the power
// limit, and the tip heats with power and loses heat to the room. Stand leads to sleep after the
// tool's sleep delay and sleep to hibernation after its hibernation delay. Counters advance with
// simulated time. Faults (station and port errors, alarms, fuse, robot mode) are injected by
// tests and the demo through the public setters.
#pragma once

#include "jointshape.h"
#include "simdevice.h"

#include <QList>
#include <optional>

namespace tipscope::sim {

// A joint in progress on a port: its shape and how far along it is.
struct ActiveJoint {
    JointShape shape;
    double elapsedMs = 0;
    SimJoint made; // its reads filled in as the tip is read
};

struct SimPort {
    int tool = 0;
    int status = 0; // 0 working, 1 stand, 2 sleep, 3 hibernation
    bool cooling = false;
    bool suction = false;
    int motor = 0; // 0 off, 1 forward, 2 backward (ALE)
    double tip = 25.0;
    int power = 0; // per mille
    int error = 0;
    int alarmFlags = 0; // 1 high, 10 low
    double secondsInStatus = 0;
    double highFor = 0, lowFor = 0;
    double pluggedS = 0, workS = 0, sleepS = 0, hibernationS = 0, noToolS = 0;
    int sleepCycles = 0, desolderCycles = 0;
    std::optional<ActiveJoint> joint; // startJoint()
    double wear = 0;                  // share by which the tip's recoveries are slower
    double dispensedDmm = 0;          // ALE
    int dispensedCycles = 0;
    double dispenseLeftDmm = 0;
};

class SimStation : public SimDevice {
public:
    explicit SimStation(const QString &family, int address = 1);

    [[nodiscard]] int portCount() const { return int(m_ports.size()); }
    [[nodiscard]] const SimPort &port(int n) const { return m_ports.at(n - 1); }
    void setTool(int port, int tool);
    void setPortError(int port, int code);
    void setStationError(int code) { m_stationError = code; }
    void latchAlarm(int port, int flags) { m_ports[port - 1].alarmFlags |= flags; }
    void setFuse(bool present) { m_fusePresent = present; }
    void setStatus(int port, int status);
    // A joint on the port now (JointShape): the tip falls `depthK` below its target and is back
    // within the band after `recoveryMs`, lengthened by the port's wear. A port that cannot make
    // one (canMakeJoint()) makes none: nullopt. What was made is also kept for takeMadeJoints().
    std::optional<SimJoint> startJoint(int port, int depthK, qint64 recoveryMs);
    // The same for a joint of any shape; the wear lengthens its recovery.
    std::optional<SimJoint> startJoint(int port, JointSpec spec);
    // How far the tip readings wobble around the true tip (±K), and whether they wobble during a
    // joint too. By default a small wobble between joints only, so that a joint's readings are
    // the shape's own (what the tests of exact figures need); a shape set asks for more.
    void setReadingNoise(double amplitudeK, bool duringJoints);
    // At work with a tool, its tip settled at the target, no joint in progress.
    [[nodiscard]] bool canMakeJoint(int port) const;
    // The joints made since the last call, with their start in this station's time (nowMs()).
    [[nodiscard]] QList<SimJoint> takeMadeJoints();
    // The same for the joints that ended, with how their tip was read (SimJoint::reads).
    [[nodiscard]] QList<SimJoint> takeEndedJoints();
    // A worn tip: its recoveries take `share` longer (0.3: 30 % slower).
    void setWear(int port, double share) { m_ports[port - 1].wear = qMax(0.0, share); }
    // Simulated milliseconds since the station was made.
    [[nodiscard]] qint64 nowMs() const { return m_nowMs; }

    void advance(int ms) override;
    void restoreFactorySettings() override;

    static constexpr double kAmbient = 25.0;

protected:
    std::optional<protocol::Value> readLive(const protocol::ResolvedCommand &cmd) override;
    std::optional<QByteArray> applyWrite(const protocol::ResolvedCommand &cmd,
                                         qint64 value) override;

private:
    void step(SimPort &p, int portNumber, double dt);
    void stepJoint(SimPort &p, double target, double dt);
    void updateSleep(SimPort &p, int portNumber, double dt);
    void updateAlarms(SimPort &p, int portNumber, double dt);
    [[nodiscard]] double targetFor(const SimPort &p, int portNumber) const;
    [[nodiscard]] QByteArray toolCode(char letter, int port, int tool) const;
    [[nodiscard]] std::optional<qint64> counterValue(const QByteArray &pattern,
                                                     const SimPort &p) const;

    QList<SimPort> m_ports;
    int m_stationError = 0;
    bool m_hasAlarmDelays = false; // the family has HDx/LDx
    bool m_fusePresent = true;
    bool m_fuseIgnored = false;
    double m_noisePhase = 0;
    double m_noiseK = kDemoWobbleK;
    bool m_noiseDuringJoints = false;
    qint64 m_nowMs = 0;
    QList<SimJoint> m_madeJoints;
    QList<SimJoint> m_endedJoints;
    QMap<QByteArray, qint64> m_savedSelected; // W-NVS snapshot of STx
};

} // namespace tipscope::sim
