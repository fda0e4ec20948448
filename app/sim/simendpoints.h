// Where tipscope-sim meets the outside world: a PTY it creates, an existing serial device (one
// end of a socat pair, or a real port), or a raw TCP server like a serial device server. Each
// endpoint forwards received bytes to the SimLine and the line's answers back out. A client that
// does not read its answers costs at most kMaxUnsentBytes: answers beyond that are dropped and
// counted (SimLineStats::unsentBytes), as a device's small output buffer would overflow. What a
// client sends is taken kMaxUnreadBytes at a time; the rest waits with the sender, so a flood of
// requests costs no more memory than that either.
#pragma once

#include "base/outcome.h"

#include <QObject>
#include <QString>

class QSocketNotifier;
class QSerialPort;
class QTcpServer;
class QTcpSocket;

namespace tipscope::sim {

class SimLine;

inline constexpr qint64 kMaxUnsentBytes = 64 * 1024;
inline constexpr qint64 kMaxUnreadBytes = 64 * 1024;

// A PTY pair created with posix_openpt. The slave side is what a client opens; its path is
// printed, and optionally kept as a symbolic link so that it survives unplug()/plug().
class PtyEndpoint : public QObject {
    Q_OBJECT
public:
    PtyEndpoint(SimLine &line, const QString &linkPath, QObject *parent = nullptr);
    ~PtyEndpoint() override;
    [[nodiscard]] base::Outcome<void> plug();
    void unplug();
    [[nodiscard]] QString slavePath() const { return m_slavePath; }

private:
    void onReadable();
    SimLine &m_line;
    QString m_linkPath;
    QString m_slavePath;
    int m_master = -1;
    int m_slave = -1;
    QSocketNotifier *m_notifier = nullptr;
};

class SerialDeviceEndpoint : public QObject {
    Q_OBJECT
public:
    SerialDeviceEndpoint(SimLine &line, const QString &device, QObject *parent = nullptr);
    [[nodiscard]] base::Outcome<void> open();

private:
    SimLine &m_line;
    QSerialPort *m_port;
};

class TcpEndpoint : public QObject {
    Q_OBJECT
public:
    TcpEndpoint(SimLine &line, QObject *parent = nullptr);
    [[nodiscard]] base::Outcome<void> listen(const QString &hostPort);
    [[nodiscard]] quint16 port() const;

private:
    void onNewConnection();
    SimLine &m_line;
    QTcpServer *m_server;
    QTcpSocket *m_client = nullptr;
};

} // namespace tipscope::sim
