#include "simendpoints.h"

#include "link/socketsend.h"
#include "sim/simline.h"

#include <QFile>
#include <QHostAddress>
#include <QSerialPort>
#include <QSocketNotifier>
#include <QTcpServer>
#include <QTcpSocket>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace tipscope::sim {

using base::failure;
using base::Outcome;

namespace {

// Writes `bytes` unless the client already has kMaxUnsentBytes waiting; counts what is dropped.
void writeBounded(QIODevice &io, const QByteArray &bytes, SimLine &line) {
    if (io.bytesToWrite() + bytes.size() > kMaxUnsentBytes) {
        line.countUnsent(bytes.size());
        return;
    }
    io.write(bytes);
}

} // namespace

PtyEndpoint::PtyEndpoint(SimLine &line, const QString &linkPath, QObject *parent)
    : QObject(parent)
    , m_line(line)
    , m_linkPath(linkPath) {
    connect(&m_line, &SimLine::transmit, this, [this](const QByteArray &bytes) {
        if (m_master < 0)
            return; // unplugged: the bytes are lost, as on a pulled cable
        // Non-blocking: when the client does not read, the PTY's buffer fills and the rest is lost.
        const ssize_t n = ::write(m_master, bytes.constData(), size_t(bytes.size()));
        if (n < bytes.size())
            m_line.countUnsent(bytes.size() - qMax<ssize_t>(n, 0));
    });
}

PtyEndpoint::~PtyEndpoint() {
    unplug();
}

Outcome<void> PtyEndpoint::plug() {
    m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (m_master < 0 || ::grantpt(m_master) != 0 || ::unlockpt(m_master) != 0)
        return failure(
            QStringLiteral("cannot create a PTY: %1").arg(QString::fromLocal8Bit(strerror(errno))));
    m_slavePath = QString::fromLocal8Bit(::ptsname(m_master));
    m_line.clearWire(); // a new cable: nothing of the old one is still on its way
    // Holding the slave open keeps the master readable while no client is attached, and raw
    // mode stops the line discipline from echoing or translating the protocol's bytes.
    m_slave = ::open(m_slavePath.toLocal8Bit().constData(), O_RDWR | O_NOCTTY);
    termios tio{};
    if (m_slave >= 0 && ::tcgetattr(m_slave, &tio) == 0) {
        ::cfmakeraw(&tio);
        ::tcsetattr(m_slave, TCSANOW, &tio);
    }
    ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
    m_notifier = new QSocketNotifier(m_master, QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &PtyEndpoint::onReadable);
    if (!m_linkPath.isEmpty()) {
        QFile::remove(m_linkPath);
        if (!QFile::link(m_slavePath, m_linkPath))
            return failure(QStringLiteral("cannot create the link %1").arg(m_linkPath));
    }
    return {};
}

void PtyEndpoint::unplug() {
    delete m_notifier;
    m_notifier = nullptr;
    if (m_slave >= 0)
        ::close(m_slave);
    if (m_master >= 0)
        ::close(m_master);
    m_slave = m_master = -1;
    if (!m_linkPath.isEmpty())
        QFile::remove(m_linkPath);
}

void PtyEndpoint::onReadable() {
    char buf[512];
    for (;;) {
        const ssize_t n = ::read(m_master, buf, sizeof buf);
        if (n > 0) {
            m_line.receive(QByteArray(buf, int(n)));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        break;
    }
}

SerialDeviceEndpoint::SerialDeviceEndpoint(SimLine &line, const QString &device, QObject *parent)
    : QObject(parent)
    , m_line(line)
    , m_port(new QSerialPort(device, this)) {
    m_port->setReadBufferSize(kMaxUnreadBytes);
    connect(m_port, &QSerialPort::readyRead, this, [this] { m_line.receive(m_port->readAll()); });
    connect(&m_line, &SimLine::transmit, m_port, [this](const QByteArray &b) {
        if (m_port->isOpen())
            writeBounded(*m_port, b, m_line);
    });
}

Outcome<void> SerialDeviceEndpoint::open() {
    m_port->setBaudRate(QSerialPort::Baud19200);
    if (!m_port->open(QIODevice::ReadWrite))
        return failure(
            QStringLiteral("cannot open %1: %2").arg(m_port->portName(), m_port->errorString()));
    m_port->clear();
    return {};
}

TcpEndpoint::TcpEndpoint(SimLine &line, QObject *parent)
    : QObject(parent)
    , m_line(line)
    , m_server(new QTcpServer(this)) {
    connect(m_server, &QTcpServer::newConnection, this, &TcpEndpoint::onNewConnection);
    connect(&m_line, &SimLine::transmit, this, [this](const QByteArray &b) {
        if (!m_client)
            return;
        // Sent at once, as a device server does, not at the event loop's next turn.
        const qsizetype sent = link::sendNow(*m_client, b);
        if (sent < b.size())
            writeBounded(*m_client, sent > 0 ? b.mid(sent) : b, m_line);
    });
}

Outcome<void> TcpEndpoint::listen(const QString &hostPort) {
    const int colon = hostPort.lastIndexOf(QLatin1Char(':'));
    bool ok = false;
    const int port = hostPort.mid(colon + 1).toInt(&ok);
    const QHostAddress host(hostPort.left(colon));
    if (colon < 0 || !ok || port < 0 || port > 65535 || host.isNull())
        return failure(QStringLiteral("'%1' is not HOST:PORT").arg(hostPort));
    if (!m_server->listen(host, quint16(port)))
        return failure(m_server->errorString());
    return {};
}

quint16 TcpEndpoint::port() const {
    return m_server->serverPort();
}

void TcpEndpoint::onNewConnection() {
    // A serial device server has one line: the newest client takes it over.
    QTcpSocket *next = m_server->nextPendingConnection();
    if (m_client)
        m_client->deleteLater();
    m_client = next;
    m_client->setReadBufferSize(kMaxUnreadBytes);
    // A paced answer leaves a byte at a time. With Nagle's algorithm each byte after the first
    // would wait for the client's delayed acknowledgement (up to 40 ms on Linux), a wait no
    // serial wire has: a line of 71 transactions a second carried 20.
    m_client->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_line.clearWire();
    connect(m_client, &QTcpSocket::readyRead, this, [this, next] {
        if (next == m_client)
            m_line.receive(next->readAll());
    });
    connect(m_client, &QTcpSocket::disconnected, this, [this, next] {
        if (next == m_client)
            m_client = nullptr;
        next->deleteLater();
    });
}

} // namespace tipscope::sim
