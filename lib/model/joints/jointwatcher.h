// JointWatcher: finds the joints of every port of the watched stations, live, from the session's
// telemetry.
//
// Each port's history gets a JointDetector. When samples arrive (Telemetry::samplesAdded), the
// new ones are fed to it in time order with the port's tool of the moment; a recorded gap in the
// history (line down, no answer, disconnected) reaches it as a gap, so no joint is measured
// across one. unwatch() ends a joint in progress as incomplete. Every joint that ends is
// jointEnded(), judged by the limits the rules give for its port and tool (setRules()). Each
// recovered joint also counts towards its tip's wear (TipWear); a tip that has become slower is
// tipWearing(), once per tool plugged in (a change of the port's tool starts it afresh).
//
// It reads the same samples the charts draw, so what it measures is what a person sees.
#pragma once

#include "model/device/stationmodel.h"
#include "model/joints/jointdetector.h"
#include "model/joints/jointlimitrules.h"
#include "model/joints/tipwear.h"
#include "model/telemetry/telemetry.h"

#include <QObject>
#include <QPointer>
#include <map>

namespace tipscope::model {

class JointWatcher : public QObject {
    Q_OBJECT
public:
    explicit JointWatcher(Telemetry &telemetry, QObject *parent = nullptr);

    // One port's history as the watcher reads it: whose it is, the tool on it (asked at each
    // feed, so a tool change starts the tip's wear afresh), and the scale of its power series.
    struct Channel {
        DeviceIdentity device;
        int port = 0;
        std::function<QString()> tool;
        double powerScale = 0.1; // wire units to %
    };

    // Watches every port of `station`, whose histories are under `keyOf(station, port)`.
    void watch(StationModel *station, const std::function<TelemetryKey(int port)> &keyOf);
    // Watches the history under `key` for `owner`, which need not be a device model (a
    // recording played as a line has none); watching ends when the owner is gone or unwatched.
    void watch(QObject *owner, const TelemetryKey &key, Channel channel);
    void unwatch(QObject *owner);
    void setRules(const JointLimitRules &rules) { m_rules = rules; }
    [[nodiscard]] const JointLimitRules &rules() const { return m_rules; }

    // Every joint begun before `timeMs` has ended (jointEnded() said it): each watched port was
    // fed readings up to `timeMs` and has no joint open that began before it. A port whose
    // readings stopped coming is not settled until they come again or its gap ends its joint.
    [[nodiscard]] bool settledUntil(qint64 timeMs) const;
    // The same for the ports of `device` alone: one station's board need not wait for another's.
    [[nodiscard]] bool settledUntil(qint64 timeMs, const DeviceIdentity &device) const;

    // A joint's limits broken, in words for the event log ("port 1 joint: recovery 4.2 s,
    // limit 3.0 s"); empty for a joint within them or not judged.
    [[nodiscard]] static QString warningText(const JointRecord &joint, const JointLimits &limits);

Q_SIGNALS:
    void jointEnded(const tipscope::model::JointRecord &joint);
    void tipWearing(const tipscope::model::TipWear::Notice &notice);

private:
    struct Watched {
        QPointer<QObject> owner;
        Channel channel;
        JointDetector detector;
        qint64 fedUntilMs = 0; // samples up to here are fed
        QString tool;          // the port's tool when it was last fed
    };

    void onSamplesAdded(const QList<TelemetryKey> &keys);
    void feed(Watched &w, const TelemetryBuffer &buffer);
    void emitIfEnded(const std::optional<JointRecord> &joint);

    Telemetry &m_telemetry;
    std::map<TelemetryKey, Watched> m_watched;
    JointLimitRules m_rules;
    TipWear m_wear;
};

} // namespace tipscope::model
