// Transport: a byte pipe to one serial line, whatever carries it.
//
// Implementations: SerialTransport (QSerialPort), TcpTransport (a raw TCP serial server such as
// ser2net) and SimTransport (the in-process simulator of demo mode). All are asynchronous:
// open() returns at once and ends in opened() or openFailed(); bytesWritten() reports bytes
// handed to the driver (the request queue starts its answer timeout from it); disconnected()
// says a line that was open is gone (an unplugged adapter, a dropped connection). A transport
// never reopens itself: Line decides when to try again.
#pragma once

#include <QObject>
#include <QString>

namespace tipscope::link {

enum class OpenFailure { NotFound, Permission, Busy, Other };

class Transport : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    virtual void open() = 0;
    virtual void close() = 0;
    virtual void write(const QByteArray &bytes) = 0;
    [[nodiscard]] virtual bool isOpen() const = 0;
    // "/dev/ttyUSB0 19200 8N1", "tcp 10.0.0.5:4001", "demo (simulated DME + SFR)"
    [[nodiscard]] virtual QString description() const = 0;
    // The baud rate of the serial wire (behind a TCP server too), for wire-time budgets.
    [[nodiscard]] virtual int baudRate() const = 0;

Q_SIGNALS:
    void opened();
    void openFailed(tipscope::link::OpenFailure kind, const QString &reason);
    void received(const QByteArray &bytes);
    void bytesWritten(qint64 count);
    void disconnected(const QString &reason);
};

} // namespace tipscope::link
