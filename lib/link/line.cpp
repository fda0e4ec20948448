#include "line.h"

#include "linklogging.h"
#include "ports/serialportlist.h"
#include "simtransport.h"

namespace tipscope::link {

Line::Line(std::unique_ptr<Transport> transport, const LineSettings &settings, QObject *parent)
    : QObject(parent)
    , m_transport(std::move(transport))
    , m_settings(settings) {
    m_queue.setSettings(settings.queue);
    m_queue.setTransport(m_transport.get());
    m_retryTimer.setSingleShot(true);
    connect(&m_retryTimer, &QTimer::timeout, this, [this] { m_transport->open(); });
    connect(m_transport.get(), &Transport::opened, this, &Line::onOpened);
    connect(m_transport.get(), &Transport::openFailed, this, &Line::onOpenFailed);
    connect(m_transport.get(), &Transport::disconnected, this, &Line::onLost);
    connect(&m_queue, &RequestQueue::timeoutStreak, this, &Line::onTimeoutStreak);
}

Line::~Line() {
    m_queue.stop(tr("the line was closed"));
    m_transport->close();
}

QString lineIdentityName(const LineSettings &settings) {
    switch (settings.kind) {
    case LineSettings::Kind::Demo:
        return QStringLiteral("demo");
    case LineSettings::Kind::Tcp:
        return QStringLiteral("%1:%2").arg(settings.tcpHost).arg(settings.tcpPort);
    case LineSettings::Kind::Serial:
        break;
    }
    const QString &name = settings.serial.portName;
    const QString path = name.contains(QLatin1Char('/')) ? name : QStringLiteral("/dev/") + name;
    const QString byId = describePort(path).byIdPath;
    return byId.isEmpty() ? path : byId;
}

std::unique_ptr<Transport> Line::makeTransport(const LineSettings &s, sim::SimLine *demoLine) {
    switch (s.kind) {
    case LineSettings::Kind::Serial:
        return std::make_unique<SerialTransport>(s.serial);
    case LineSettings::Kind::Tcp: {
        auto tcp = std::make_unique<TcpTransport>(s.tcpHost, s.tcpPort, s.serial.baudRate);
        tcp->setConnectTimeoutMs(s.tcpConnectTimeoutMs);
        return tcp;
    }
    case LineSettings::Kind::Demo:
        Q_ASSERT(demoLine);
        return std::make_unique<SimTransport>(*demoLine);
    }
    return nullptr;
}

QString Line::stateText() const {
    switch (m_state) {
    case State::Closed:
        return tr("disconnected");
    case State::Opening:
        return tr("connecting to %1").arg(m_transport->description());
    case State::Open:
        return tr("connected: %1").arg(m_transport->description());
    case State::Retrying:
        // A line that never opened was not disconnected: the port or server is not there yet.
        if (!m_everOpened)
            return tr("cannot open %1, retrying every %2 s: %3")
                .arg(m_transport->description())
                .arg(m_settings.reconnectIntervalMs / 1000.0)
                .arg(m_lastError);
        return tr("disconnected, retrying every %1 s: %2")
            .arg(m_settings.reconnectIntervalMs / 1000.0)
            .arg(m_lastError);
    case State::Failed:
        return tr("cannot connect: %1").arg(m_lastError);
    }
    return {};
}

void Line::setState(State s, const QString &detail) {
    m_state = s;
    m_queue.tap().note(stateText());
    qCDebug(lcLink).noquote() << stateText() << "(reconnects:" << m_reconnects << ")";
    Q_EMIT stateChanged(s, detail);
}

void Line::open() {
    m_retryTimer.stop();
    setState(State::Opening, m_transport->description());
    m_transport->open();
}

void Line::close() {
    m_retryTimer.stop();
    m_transport->close();
    m_queue.lineLost(tr("disconnected by the user"));
    setState(State::Closed, {});
}

void Line::onOpened() {
    if (m_state == State::Closed) { // closed by the user while the open was on its way
        m_transport->close();
        return;
    }
    if (m_everOpened)
        ++m_reconnects;
    m_everOpened = true;
    m_lastError.clear();
    m_queue.lineOpened();
    setState(State::Open, m_transport->description());
}

void Line::onOpenFailed(OpenFailure kind, const QString &reason) {
    m_lastError = reason;
    m_lastFailure = kind;
    if (m_state == State::Closed)
        return; // closed by the user meanwhile
    if (m_everOpened || m_settings.retryInitialOpen) {
        setState(State::Retrying, reason);
        m_retryTimer.start(m_settings.reconnectIntervalMs);
        return;
    }
    setState(State::Failed, reason);
}

void Line::onLost(const QString &reason) {
    m_lastError = reason;
    m_queue.lineLost(reason);
    setState(State::Retrying, reason);
    m_retryTimer.start(m_settings.reconnectIntervalMs);
}

void Line::onTimeoutStreak(int count) {
    if (m_settings.suspectAfterTimeouts <= 0 || count < m_settings.suspectAfterTimeouts ||
        m_state != State::Open)
        return;
    qCDebug(lcLink) << count << "requests in a row unanswered: closing and reconnecting";
    m_transport->close();
    onLost(tr("no answer to %1 requests in a row (cable unplugged, device off, "
              "or wrong addressing?)")
               .arg(count));
}

} // namespace tipscope::link
