// TcpTransport: a Transport to a raw TCP serial server (ser2net, a serial device server on the
// factory network). The server owns the serial settings; baudRate() is the wire's nominal rate,
// used only for timeout budgets. A connection that is not made within the connect timeout (a
// server whose accept queue is full, a host that drops the packets) fails with openFailed()
// instead of waiting for the system's own limit of a minute or more.
#pragma once

#include "transport.h"

#include <QTcpSocket>
#include <QTimer>

namespace tipscope::link {

class TcpTransport : public Transport {
    Q_OBJECT
public:
    static constexpr int kDefaultConnectTimeoutMs = 5000;

    TcpTransport(const QString &host, quint16 port, int wireBaud = 19200,
                 QObject *parent = nullptr);
    void setConnectTimeoutMs(int ms) { m_connectTimer.setInterval(ms); }

    void open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    [[nodiscard]] bool isOpen() const override;
    [[nodiscard]] QString description() const override;
    [[nodiscard]] int baudRate() const override { return m_baud; }

    // Parses "host:port"; returns false for anything else.
    static bool parseHostPort(const QString &text, QString *host, quint16 *port);

private:
    void onConnectTimeout();

    QString m_host;
    quint16 m_port;
    int m_baud;
    QTcpSocket m_socket;
    QTimer m_connectTimer;
    bool m_wasConnected = false;
};

} // namespace tipscope::link
