#include "mqttpump.h"

#include <QPointer>
#include <QSocketNotifier>
#include <cerrno>
#include <mosquitto.h>
#include <poll.h>

namespace tipscope::mqtt {

namespace {

constexpr int kTickMs = 1000;
// libmosquitto reads about one packet a call: a burst (PUBACKs of a backlog, a subscriber's
// messages) is read up to this many packets a turn of the event loop rather than one.
constexpr int kReadBurst = 64;

// Qt may still be delivering an activation of the notifier being replaced; deleting it later
// is always safe, and disabling it first keeps the event loop off the closed descriptor.
void retire(std::unique_ptr<QSocketNotifier> &notifier) {
    if (!notifier)
        return;
    notifier->setEnabled(false);
    notifier.release()->deleteLater();
}

bool isHungUp(int socket) {
    pollfd entry{socket, 0, 0}; // hang-ups and errors are reported whatever is asked for
    return ::poll(&entry, 1, 0) == 1 && (entry.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
}

bool hasInput(int socket) {
    pollfd entry{socket, POLLIN, 0};
    return ::poll(&entry, 1, 0) == 1 && entry.revents == POLLIN;
}

} // namespace

MqttPump::MqttPump(QObject *parent)
    : QObject(parent) {
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, &MqttPump::onTick);
}

MqttPump::~MqttPump() = default;

void MqttPump::attach(mosquitto *client) {
    dropNotifiers();
    m_client = client;
    m_abandoned = -1;
    sync();
}

void MqttPump::dropNotifiers() {
    retire(m_read);
    retire(m_write);
    m_socket = -1;
    m_tick.stop();
}

void MqttPump::sync() {
    int socket = m_client ? mosquitto_socket(m_client) : -1;
    if (socket == m_abandoned)
        socket = -1;
    if (socket != m_socket) {
        dropNotifiers();
        if (socket < 0)
            return;
        m_socket = socket;
        m_read = std::make_unique<QSocketNotifier>(socket, QSocketNotifier::Read);
        connect(m_read.get(), &QSocketNotifier::activated, this, &MqttPump::onReadable);
        m_write = std::make_unique<QSocketNotifier>(socket, QSocketNotifier::Write);
        connect(m_write.get(), &QSocketNotifier::activated, this, &MqttPump::onWritable);
        m_tick.start();
    }
    const bool wantsWrite = m_write && mosquitto_want_write(m_client);
    if (m_write)
        m_write->setEnabled(wantsWrite);
    // Outside its own handling, a sync follows something the client did (connected, published,
    // subscribed): an answer is due.
    if (m_quiet && (wantsWrite || !m_servicing))
        stayAwake();
}

void MqttPump::setQuiet(bool on) {
    m_quiet = on;
    if (m_read && !on)
        m_read->setEnabled(true);
}

bool MqttPump::watchesReads() const {
    return m_read && m_read->isEnabled();
}

void MqttPump::stayAwake() {
    m_idleTicks = 0;
    if (m_read)
        m_read->setEnabled(true);
}

void MqttPump::report(int rc) {
    const int errnoValue = errno;
    const int socket = m_client ? mosquitto_socket(m_client) : -1;
    if (rc == MOSQ_ERR_SUCCESS && socket >= 0 && socket == m_socket && isHungUp(socket)) {
        // What the broker sent before it hung up (a TLS alert) may still wait to be read.
        const int readRc = mosquitto_loop_read(m_client, 1);
        if (mosquitto_socket(m_client) != socket) {
            Q_EMIT serviced(readRc, errno);
            return;
        }
        dropNotifiers();
        m_abandoned = socket;
        Q_EMIT hungUp();
        return;
    }
    const bool outer = !m_servicing;
    m_servicing = true;
    const QPointer<MqttPump> alive(this); // its owner may end with what it handles
    Q_EMIT serviced(rc, errnoValue);
    if (alive && outer)
        m_servicing = false;
}

void MqttPump::onReadable() {
    if (!m_client)
        return;
    int rc = mosquitto_loop_read(m_client, 1);
    for (int i = 1; i < kReadBurst && rc == MOSQ_ERR_SUCCESS &&
                    mosquitto_socket(m_client) == m_socket && hasInput(m_socket);
         ++i)
        rc = mosquitto_loop_read(m_client, 1);
    report(rc);
}

void MqttPump::onWritable() {
    if (!m_client)
        return;
    if (m_quiet)
        stayAwake();
    report(mosquitto_loop_write(m_client, 1));
}

void MqttPump::onTick() {
    if (!m_client)
        return;
    const int socket = m_socket;
    if (m_quiet && m_read && !m_read->isEnabled() && hasInput(socket)) {
        const QPointer<MqttPump> alive(this); // its owner may end with what the read caused
        onReadable();
        if (!alive)
            return;
    }
    if (m_socket != socket || !m_client)
        return; // the read closed or replaced the socket, and said so
    report(mosquitto_loop_misc(m_client));
    if (m_quiet && m_read && ++m_idleTicks >= kQuietAfterTicks)
        m_read->setEnabled(false);
}

} // namespace tipscope::mqtt
