// TcpTransport: a Transport to a raw TCP serial server (ser2net, a serial device server on the
// factory network). The server owns the serial settings; baudRate() is the wire's nominal rate,
// used only for timeout budgets.
#pragma once

#include "transport.h"

#include <QTcpSocket>

namespace tipscope::link {

class TcpTransport : public Transport {
    Q_OBJECT
public:
    TcpTransport(const QString &host, quint16 port, int wireBaud = 19200,
                 QObject *parent = nullptr);

    void open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    [[nodiscard]] bool isOpen() const override;
    [[nodiscard]] QString description() const override;
    [[nodiscard]] int baudRate() const override { return m_baud; }

    // Parses "host:port"; returns false for anything else.
    static bool parseHostPort(const QString &text, QString *host, quint16 *port);

private:
    QString m_host;
    quint16 m_port;
    int m_baud;
    QTcpSocket m_socket;
    bool m_wasConnected = false;
};

} // namespace tipscope::link
