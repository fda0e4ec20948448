#include "mqttpump.h"

#include <QSocketNotifier>
#include <cerrno>
#include <mosquitto.h>

namespace tipscope::mqtt {

namespace {

constexpr int kTickMs = 1000;

// Qt may still be delivering an activation of the notifier being replaced; deleting it later
// is always safe, and disabling it first keeps the event loop off the closed descriptor.
void retire(std::unique_ptr<QSocketNotifier> &notifier) {
    if (!notifier)
        return;
    notifier->setEnabled(false);
    notifier.release()->deleteLater();
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
    sync();
}

void MqttPump::dropNotifiers() {
    retire(m_read);
    retire(m_write);
    m_socket = -1;
    m_tick.stop();
}

void MqttPump::sync() {
    const int socket = m_client ? mosquitto_socket(m_client) : -1;
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
    if (m_write)
        m_write->setEnabled(mosquitto_want_write(m_client));
}

void MqttPump::report(int rc) {
    Q_EMIT serviced(rc, errno);
}

void MqttPump::onReadable() {
    if (m_client)
        report(mosquitto_loop_read(m_client, 1));
}

void MqttPump::onWritable() {
    if (m_client)
        report(mosquitto_loop_write(m_client, 1));
}

void MqttPump::onTick() {
    if (m_client)
        report(mosquitto_loop_misc(m_client));
}

} // namespace tipscope::mqtt
