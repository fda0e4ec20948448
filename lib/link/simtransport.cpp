#include "simtransport.h"

#include "sim/simline.h"

#include <QTimer>

namespace tipscope::link {

SimTransport::SimTransport(sim::SimLine &line, QObject *parent)
    : Transport(parent)
    , m_line(line) {
    connect(&m_line, &sim::SimLine::transmit, this, [this](const QByteArray &bytes) {
        if (m_open)
            QTimer::singleShot(0, this, [this, bytes] {
                if (m_open)
                    Q_EMIT received(bytes);
            });
    });
}

void SimTransport::open() {
    QTimer::singleShot(0, this, [this] {
        if (!m_plugged) {
            Q_EMIT openFailed(OpenFailure::NotFound, tr("the simulated line is unplugged"));
            return;
        }
        m_open = true;
        Q_EMIT opened();
    });
}

void SimTransport::close() {
    m_open = false;
}

void SimTransport::write(const QByteArray &bytes) {
    if (!m_open)
        return;
    QTimer::singleShot(0, this, [this, bytes] {
        if (!m_open)
            return;
        Q_EMIT bytesWritten(bytes.size());
        m_line.receive(bytes);
    });
}

QString SimTransport::description() const {
    QStringList names;
    for (const auto *d : m_line.devices())
        names.append(d->family().name);
    return tr("demo (simulated %1)").arg(names.join(QLatin1String(" + ")));
}

int SimTransport::baudRate() const {
    return m_line.baud() > 0 ? m_line.baud() : 19200;
}

void SimTransport::setPlugged(bool plugged) {
    m_plugged = plugged;
    if (!plugged && m_open) {
        m_open = false;
        Q_EMIT disconnected(tr("the simulated cable was pulled"));
    }
}

} // namespace tipscope::link
