// Drives one libmosquitto client from the Qt event loop, so nothing ever blocks on the network:
// its socket on a read notifier (always) and a write notifier (only while libmosquitto has
// something to write, so a writable socket never wakes the loop for nothing), and a one-second
// timer for mosquitto_loop_misc (keep-alive pings, and noticing a broker that stopped answering).
// Idle and connected, that is one wake-up a second.
//
// After every libmosquitto call it makes, the pump emits `serviced` with the return code and
// errno as the call left it; the owner handles what the call caused and then calls sync(), as
// it must after anything else that may have opened, closed or queued on the socket (connecting,
// publishing, disconnecting).
#pragma once

#include <QObject>
#include <QTimer>
#include <memory>

class QSocketNotifier;
struct mosquitto;

namespace tipscope::mqtt {

class MqttPump : public QObject {
    Q_OBJECT
public:
    explicit MqttPump(QObject *parent = nullptr);
    ~MqttPump() override;

    // nullptr stops watching. The client must outlive the attachment.
    void attach(mosquitto *client);
    // Follows the client's socket: new notifiers for a new socket, none for a closed one, the
    // write notifier on exactly while libmosquitto wants to write.
    void sync();

Q_SIGNALS:
    void serviced(int rc, int errnoValue);

private:
    void dropNotifiers();
    void report(int rc);
    void onReadable();
    void onWritable();
    void onTick();

    mosquitto *m_client = nullptr;
    int m_socket = -1;
    std::unique_ptr<QSocketNotifier> m_read;
    std::unique_ptr<QSocketNotifier> m_write;
    QTimer m_tick;
};

} // namespace tipscope::mqtt
