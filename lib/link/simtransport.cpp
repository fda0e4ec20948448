#include "simtransport.h"

#include "sim/simline.h"

#include <QTimer>

namespace tipscope::link {

SimTransport::SimTransport(sim::SimLine &line, QObject *parent)
    : Transport(parent)
    , m_line(line) {
    // The line transmits from its own timer or from the queued call that wrote to it, never
    // inside write(), so its bytes are handed on at once. Queuing them again would let a
    // request's answer timer that fell due in the same pass of the event loop (the thread held
    // up past the answer budget) fire before an answer that had come in time: a real port's
    // bytes are in the kernel by then, and both event loops read them before running timers.
    connect(&m_line, &sim::SimLine::transmit, this, [this](const QByteArray &bytes) {
        if (m_open)
            Q_EMIT received(bytes);
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
