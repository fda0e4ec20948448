// A station's condition for CFX's StationStateChanged, from its live model: what its ports and its
// link report now (cfxmessages.h maps each condition to a SEMI E10 state, docs/cfx.md). Live, not
// journaled: a state describes the present, as EndpointConnected does.
//
// conditionOf() ranks what the station reports: a lost link first (what it last said is no
// longer known), then an error of the station or of a port, then the most active port (a tool
// out of its stand, in its stand, asleep, hibernating). Before any port's status was read the
// condition is unknown. StationStateWatcher follows one station and says each change, with how
// long the old condition lasted when it saw that condition begin.
#pragma once

#include "cfxmessages.h"

#include "model/device/stationmodel.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <optional>

namespace tipscope::cfx {

[[nodiscard]] std::optional<StationCondition> conditionOf(const model::StationModel &station);

class StationStateWatcher : public QObject {
    Q_OBJECT
public:
    explicit StationStateWatcher(model::StationModel &station, QObject *parent = nullptr);

    [[nodiscard]] std::optional<StationCondition> condition() const { return m_condition; }
    [[nodiscard]] model::StationModel *station() const { return m_station; }

Q_SIGNALS:
    // `lastedMs` empty: the old condition began before the watcher saw the station.
    void changed(tipscope::cfx::StationCondition before, std::optional<qint64> lastedMs,
                 tipscope::cfx::StationCondition after);

private:
    void update();

    QPointer<model::StationModel> m_station;
    std::optional<StationCondition> m_condition;
    QElapsedTimer m_since; // valid once a condition was seen to begin
};

} // namespace tipscope::cfx
