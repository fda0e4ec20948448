// Drives one libmosquitto client from the Qt event loop, so nothing ever blocks on the network:
// its socket on a read notifier (always) and a write notifier (only while libmosquitto has
// something to write, so a writable socket never wakes the loop for nothing), and a one-second
// timer for mosquitto_loop_misc (keep-alive pings, and noticing a broker that stopped answering).
// Idle and connected, that is one wake-up a second.
//
// libmosquitto 2.0.11 does not notice a socket that failed during its non-blocking TLS handshake
// (a refused or reset connection): SSL_connect reports a system error, libmosquitto keeps
// waiting, and the hung-up socket wakes the loop without end. So after every call the pump
// asks the socket itself (poll with no wait); if it hung up while libmosquitto says all is
// well, the pump stops watching it and emits `hungUp`. The next connect closes it.
//
// A client that is idle but for its own few messages (a device's presence, one of dozens) need
// not be watched between them: quiet (setQuiet()), its read notifier is on only from anything it
// sends until kQuietAfterTicks ticks later, long after the broker's answer, and each tick reads
// what came meanwhile (a ping's answer, a hang-up). Every watched socket costs each turn of the
// event loop a look by poll(), so dozens of idle presence sockets weighed on every wire's byte.
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
    // True while a socket is watched: false once it closed or hung up.
    [[nodiscard]] bool watching() const { return m_socket >= 0; }
    // Follows the client's socket: new notifiers for a new socket, none for a closed one, the
    // write notifier on exactly while libmosquitto wants to write.
    void sync();
    void setQuiet(bool on);
    // Whether the event loop watches the socket for reading now.
    [[nodiscard]] bool watchesReads() const;
    static constexpr int kQuietAfterTicks = 2;

Q_SIGNALS:
    void serviced(int rc, int errnoValue);
    void hungUp();

private:
    void dropNotifiers();
    void report(int rc);
    void onReadable();
    void onWritable();
    void onTick();
    void stayAwake();

    mosquitto *m_client = nullptr;
    int m_socket = -1;
    int m_abandoned = -1; // a hung-up socket libmosquitto still holds
    std::unique_ptr<QSocketNotifier> m_read;
    std::unique_ptr<QSocketNotifier> m_write;
    QTimer m_tick;
    bool m_quiet = false;
    bool m_servicing = false; // while `serviced` is being handled
    int m_idleTicks = 0;
};

} // namespace tipscope::mqtt
