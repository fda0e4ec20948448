#include "serialtransport.h"

#include "link/ports/portdiagnostics.h"

#include <QFileInfo>

namespace tipscope::link {

QString SerialSettings::frameFormat() const {
    const char parityChar = parity == QSerialPort::EvenParity  ? 'E'
                            : parity == QSerialPort::OddParity ? 'O'
                            : parity == QSerialPort::NoParity  ? 'N'
                                                               : '?';
    return QStringLiteral("%1%2%3")
        .arg(int(dataBits))
        .arg(QLatin1Char(parityChar))
        .arg(stopBits == QSerialPort::TwoStop ? 2 : 1);
}

SerialTransport::SerialTransport(const SerialSettings &settings, QObject *parent)
    : Transport(parent)
    , m_settings(settings) {
    m_port.setPortName(settings.portName);
    connect(&m_port, &QSerialPort::readyRead, this, [this] { Q_EMIT received(m_port.readAll()); });
    connect(&m_port, &QSerialPort::bytesWritten, this, &Transport::bytesWritten);
    connect(&m_port, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
}

QString SerialTransport::description() const {
    return QStringLiteral("%1 %2 %3")
        .arg(m_settings.portName)
        .arg(m_settings.baudRate)
        .arg(m_settings.frameFormat());
}

void SerialTransport::open() {
    if (m_port.isOpen()) {
        Q_EMIT opened();
        return;
    }
    m_port.setBaudRate(m_settings.baudRate);
    m_port.setDataBits(m_settings.dataBits);
    m_port.setParity(m_settings.parity);
    m_port.setStopBits(m_settings.stopBits);
    m_port.setFlowControl(m_settings.flowControl);
    if (!m_port.open(QIODevice::ReadWrite)) {
        const QSerialPort::SerialPortError error = m_port.error();
        const OpenFailure kind = error == QSerialPort::DeviceNotFoundError ? OpenFailure::NotFound
                                 : error == QSerialPort::PermissionError   ? OpenFailure::Permission
                                 : error == QSerialPort::OpenError         ? OpenFailure::Busy
                                                                           : OpenFailure::Other;
        const QString why = explainOpenFailure(m_port.portName(), error, m_port.errorString());
        m_port.clearError();
        Q_EMIT openFailed(kind, why);
        return;
    }
    m_port.clear(); // Qt 6.4 does not flush input on open: old bytes would look like answers
    Q_EMIT opened();
}

void SerialTransport::close() {
    if (m_port.isOpen())
        m_port.close();
}

void SerialTransport::write(const QByteArray &bytes) {
    if (m_port.isOpen())
        m_port.write(bytes);
}

void SerialTransport::onError(QSerialPort::SerialPortError error) {
    if (!m_port.isOpen())
        return; // open() reports its own failures
    switch (error) {
    case QSerialPort::ResourceError:
    case QSerialPort::ReadError:
    case QSerialPort::WriteError:
        // On an unplugged adapter Qt 6.4 reports zero-byte reads as ReadError, over and over,
        // or a ResourceError whose text is the failing ioctl's ("Inappropriate ioctl for
        // device"), which tells a person nothing. A device node that is gone says it plainly.
        if (!QFileInfo::exists(devicePath()))
            lose(tr("the port %1 disappeared (unplugged?)").arg(m_settings.portName));
        else
            lose(tr("the port stopped responding (%1)").arg(m_port.errorString()));
        break;
    default:
        break;
    }
}

QString SerialTransport::devicePath() const {
    const QString &name = m_settings.portName;
    return name.startsWith(QLatin1Char('/')) ? name : QStringLiteral("/dev/") + name;
}

void SerialTransport::lose(const QString &reason) {
    m_port.clearError();
    m_port.close();
    Q_EMIT disconnected(reason);
}

} // namespace tipscope::link
