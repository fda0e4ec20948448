// SimFeeder: a simulated SFR solder feeder.
//
// Feeds at the set speed while started; in discontinuous mode it stops by itself after the set
// length. The fed length (R-FDL) restarts at each W-SFD. Counters of plugged and feeding hours
// and of metres fed advance with simulated time; the partial ones reset with their W- commands.
// An injected error code blocks feeding (but not loading, which ignores errors) until W-ECV.
#pragma once

#include "simdevice.h"

namespace tipscope::sim {

class SimFeeder : public SimDevice {
public:
    explicit SimFeeder(int address = 10);

    [[nodiscard]] bool isFeeding() const { return m_direction != 0; }
    [[nodiscard]] double fedDmm() const { return m_fedDmm; }
    void setError(int code) { m_error = code; }
    // As W-SFD and W-SSD; the demo's activity feeds without a request on the line.
    void startFeed(bool forward = true);
    void stopFeed() { m_direction = 0; }
    [[nodiscard]] int error() const { return m_error; }

    void advance(int ms) override;

protected:
    std::optional<protocol::Value> readLive(const protocol::ResolvedCommand &cmd) override;
    std::optional<QByteArray> applyWrite(const protocol::ResolvedCommand &cmd,
                                         qint64 value) override;

private:
    int m_direction = 0; // 1 forward, -1 backward, 0 stopped
    bool m_loading = false;
    double m_fedDmm = 0;
    int m_error = 0;
    double m_pluggedTotalS = 3600.0 * 512, m_pluggedPartialS = 3600.0 * 12;
    double m_feedingTotalS = 3600.0 * 140, m_feedingPartialS = 3600.0 * 3;
    double m_lengthTotalDmm = 10000.0 * 2450, m_lengthPartialDmm = 10000.0 * 61;
};

} // namespace tipscope::sim
