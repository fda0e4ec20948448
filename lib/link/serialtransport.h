// SerialTransport: a Transport over QSerialPort.
//
// Designed around the Qt 6.4 behaviour on Linux: the input is not flushed on open (so it calls
// clear() after open()); a vanished USB adapter shows up either as ResourceError or as a stream of
// ReadErrors from zero-byte reads, and both are reported once as disconnected(), as "the port
// disappeared" when its device node is gone rather than the failing ioctl's text; a permission
// failure is explained (another program holding the port, or the dialout group).
#pragma once

#include "transport.h"

#include <QSerialPort>

namespace tipscope::link {

struct SerialSettings {
    QString portName; // "/dev/ttyUSB0" or "ttyUSB0"
    int baudRate = 19200;
    QSerialPort::DataBits dataBits = QSerialPort::Data8;
    QSerialPort::Parity parity = QSerialPort::NoParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;
    QSerialPort::FlowControl flowControl = QSerialPort::NoFlowControl;

    [[nodiscard]] QString frameFormat() const; // "8N1"
};

class SerialTransport : public Transport {
    Q_OBJECT
public:
    explicit SerialTransport(const SerialSettings &settings, QObject *parent = nullptr);

    void open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    [[nodiscard]] bool isOpen() const override { return m_port.isOpen(); }
    [[nodiscard]] QString description() const override;
    [[nodiscard]] int baudRate() const override { return m_settings.baudRate; }

private:
    void onError(QSerialPort::SerialPortError error);
    void lose(const QString &reason);
    [[nodiscard]] QString devicePath() const; // "ttyUSB0" is /dev/ttyUSB0

    SerialSettings m_settings;
    QSerialPort m_port;
};

} // namespace tipscope::link
