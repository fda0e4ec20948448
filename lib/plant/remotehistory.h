// RemoteHistory: the curves of the devices a PlantWatch sees, kept from their live topics as
// telemetry ("<root>/port1": tip, setpoint and power in the catalog's wire units, at the time the
// agent measured each sample, every sample of a batch), so that a watching window draws a remote
// device's chart with the same code as a local one.
//
// A gap stays a gap: a sample without its values (no tool in the holder), the agent going offline
// and the agent's line going down break the curve until the next sample; the watcher does not
// join what it did not see. The histories are tiered like a local fleet's and forgotten when the
// watch starts over.
#pragma once

#include "model/chart/chartseries.h"
#include "model/telemetry/telemetry.h"

#include <QJsonArray>
#include <QObject>
#include <QSet>
#include <memory>

namespace tipscope::plant {

class PlantWatch;

class RemoteHistory : public QObject {
    Q_OBJECT
public:
    // `watch` must outlive the history.
    explicit RemoteHistory(const PlantWatch &watch, QObject *parent = nullptr);
    ~RemoteHistory() override;

    // Replaced when the watch starts over: hold no reference across event-loop turns.
    [[nodiscard]] const model::Telemetry &telemetry() const { return *m_telemetry; }
    [[nodiscard]] static model::TelemetryKey keyOf(const QString &root, int port);
    // The chart channels of the device at `root`: one per port that has a history, by number.
    [[nodiscard]] QList<model::ChartChannel> channels(const QString &root) const;
    // Per channel its tip (solid), setpoint (dashed) and power (dotted, right axis), in °C as the
    // agents publish them.
    [[nodiscard]] static QList<model::ChartTrace>
    traces(const QList<model::ChartChannel> &channels);

private:
    void onSamples(const QString &root, int port, const QJsonArray &samples);
    void onDeviceChanged(const QString &root);
    void forget();

    const PlantWatch &m_watch;
    std::unique_ptr<model::Telemetry> m_telemetry;
    QSet<QString> m_down; // roots whose agent is offline or whose line is down, gap marked
};

} // namespace tipscope::plant
