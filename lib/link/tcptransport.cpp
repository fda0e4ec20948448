#include "tcptransport.h"

#include "socketsend.h"

namespace tipscope::link {

TcpTransport::TcpTransport(const QString &host, quint16 port, int wireBaud, QObject *parent)
    : Transport(parent)
    , m_host(host)
    , m_port(port)
    , m_baud(wireBaud) {
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1); // short frames, no Nagle delay
    m_connectTimer.setSingleShot(true);
    m_connectTimer.setInterval(kDefaultConnectTimeoutMs);
    connect(&m_connectTimer, &QTimer::timeout, this, &TcpTransport::onConnectTimeout);
    connect(&m_socket, &QTcpSocket::connected, this, [this] {
        m_connectTimer.stop();
        m_wasConnected = true;
        Q_EMIT opened();
    });
    connect(&m_socket, &QTcpSocket::readyRead, this,
            [this] { Q_EMIT received(m_socket.readAll()); });
    connect(&m_socket, &QTcpSocket::bytesWritten, this, &Transport::bytesWritten);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError e) {
        const QString why = m_socket.errorString();
        if (m_wasConnected) {
            m_wasConnected = false;
            m_socket.abort();
            Q_EMIT disconnected(tr("the connection to %1 dropped (%2)").arg(description(), why));
            return;
        }
        const OpenFailure kind =
            e == QAbstractSocket::HostNotFoundError ? OpenFailure::NotFound : OpenFailure::Other;
        m_connectTimer.stop();
        m_socket.abort();
        Q_EMIT openFailed(kind, tr("cannot connect to %1: %2").arg(description(), why));
    });
}

bool TcpTransport::parseHostPort(const QString &text, QString *host, quint16 *port) {
    const int colon = text.lastIndexOf(QLatin1Char(':'));
    bool ok = false;
    const int p = text.mid(colon + 1).toInt(&ok);
    if (colon <= 0 || !ok || p <= 0 || p > 65535)
        return false;
    *host = text.left(colon);
    *port = quint16(p);
    return true;
}

void TcpTransport::open() {
    if (m_socket.state() == QAbstractSocket::ConnectedState) {
        Q_EMIT opened();
        return;
    }
    m_socket.abort();
    m_connectTimer.start();
    m_socket.connectToHost(m_host, m_port);
}

void TcpTransport::onConnectTimeout() {
    if (m_socket.state() == QAbstractSocket::ConnectedState)
        return;
    m_socket.abort();
    Q_EMIT openFailed(OpenFailure::Other, tr("cannot connect to %1: no connection within %2 s")
                                              .arg(description())
                                              .arg(m_connectTimer.interval() / 1000.0));
}

void TcpTransport::close() {
    m_connectTimer.stop();
    m_wasConnected = false;
    m_socket.abort();
}

void TcpTransport::write(const QByteArray &bytes) {
    if (!isOpen())
        return;
    // Out now, not at the event loop's next turn, and without the turns Qt's own path costs
    // (socketsend.h); what the socket does not take at once goes Qt's way, flushed.
    const qsizetype sent = sendNow(m_socket, bytes);
    if (sent > 0)
        Q_EMIT bytesWritten(sent);
    if (sent == bytes.size())
        return;
    m_socket.write(sent > 0 ? bytes.mid(sent) : bytes);
    m_socket.flush();
}

bool TcpTransport::isOpen() const {
    return m_socket.state() == QAbstractSocket::ConnectedState;
}

QString TcpTransport::description() const {
    return QStringLiteral("tcp %1:%2").arg(m_host).arg(m_port);
}

} // namespace tipscope::link
