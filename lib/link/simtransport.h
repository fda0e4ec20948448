// SimTransport: the in-process connection to a SimLine, for demo mode and tests.
//
// A write crosses in a queued call and the line's answer comes from its timer, so the request
// queue sees the same asynchronous order of events as with a real port. setPlugged(false) simulates
// a pulled cable: the transport reports disconnected() and refuses to open until plugged again.
#pragma once

#include "transport.h"

namespace tipscope::sim {
class SimLine;
}

namespace tipscope::link {

class SimTransport : public Transport {
    Q_OBJECT
public:
    // The line must outlive the transport.
    explicit SimTransport(sim::SimLine &line, QObject *parent = nullptr);

    void open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    [[nodiscard]] bool isOpen() const override { return m_open; }
    [[nodiscard]] QString description() const override;
    [[nodiscard]] int baudRate() const override;
    void setPlugged(bool plugged);

private:
    sim::SimLine &m_line;
    bool m_open = false;
    bool m_plugged = true;
};

} // namespace tipscope::link
