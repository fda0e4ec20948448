// Line: one serial line as the rest of TipScope sees it: a transport, its request queue, and
// the supervision that keeps it usable.
//
// open() starts the transport. When a line that was open is lost (the transport reports it, or
// `suspectAfterTimeouts` requests in a row get no answer at all), every pending request fails
// with the reason, the state becomes Retrying, and the line tries to reopen every
// `reconnectIntervalMs` until it succeeds; then the queue resumes. An initial open that fails is
// final (Failed) unless `retryInitialOpen` is set, so a command-line tool can exit at once.
#pragma once

#include "requestqueue.h"
#include "serialtransport.h"
#include "tcptransport.h"
#include "transport.h"

#include <QObject>
#include <QTimer>
#include <memory>

namespace tipscope::sim {
class SimLine;
}

namespace tipscope::link {

struct LineSettings {
    enum class Kind { Serial, Tcp, Demo };
    Kind kind = Kind::Serial;
    SerialSettings serial;
    QString tcpHost;
    quint16 tcpPort = 0;
    int tcpConnectTimeoutMs = TcpTransport::kDefaultConnectTimeoutMs;
    QueueSettings queue;
    int reconnectIntervalMs = 1000;
    int suspectAfterTimeouts = 5;
    bool retryInitialOpen = false;
};

// How the line is named in a device's identity: for a serial port its /dev/serial/by-id link when
// it has one (it names the adapter, whatever ttyUSB number it got today), else its device path;
// "host:port" for a TCP serial server; "demo" for the built-in simulated line.
[[nodiscard]] QString lineIdentityName(const LineSettings &settings);

class Line : public QObject {
    Q_OBJECT
public:
    enum class State { Closed, Opening, Open, Retrying, Failed };

    Line(std::unique_ptr<Transport> transport, const LineSettings &settings,
         QObject *parent = nullptr);
    ~Line() override;

    // Builds the transport the settings name; demo mode needs the simulated line.
    static std::unique_ptr<Transport> makeTransport(const LineSettings &settings,
                                                    sim::SimLine *demoLine);

    void open();
    void close();
    [[nodiscard]] State state() const { return m_state; }
    [[nodiscard]] QString stateText() const;
    [[nodiscard]] QString lastError() const { return m_lastError; }
    [[nodiscard]] OpenFailure lastFailure() const { return m_lastFailure; }
    [[nodiscard]] int reconnects() const { return m_reconnects; }
    [[nodiscard]] RequestQueue &queue() { return m_queue; }
    [[nodiscard]] Transport &transport() { return *m_transport; }

Q_SIGNALS:
    void stateChanged(tipscope::link::Line::State state, const QString &detail);

private:
    void setState(State s, const QString &detail);
    void onOpened();
    void onOpenFailed(OpenFailure kind, const QString &reason);
    void onLost(const QString &reason);
    void onTimeoutStreak(int count);

    std::unique_ptr<Transport> m_transport;
    LineSettings m_settings;
    RequestQueue m_queue;
    QTimer m_retryTimer;
    State m_state = State::Closed;
    QString m_lastError;
    OpenFailure m_lastFailure = OpenFailure::Other;
    bool m_everOpened = false;
    int m_reconnects = 0;
};

} // namespace tipscope::link
